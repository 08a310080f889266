"""The optional compiled kernels: F4's rows, symbolic preprocessing, pairs and modular lift (kernel/_f4rows.c,
kernel/_f4sym.c, kernel/_f4pairs.c, kernel/_f4lift.c), FGLM modulo p and its lift's exact check (kernel/_fglm.c,
kernel/_fglm_proof.c), the Hilbert-driven Buchberger algorithm modulo p (kernel/_bba.c) and Mora's reduction loop
(kernel/_mora.c): built when a C compiler is present, skipped otherwise (mech then uses its pure-Python code).
Everything else is in pyproject.toml."""
from setuptools import Extension, setup

setup(ext_modules=[Extension("mech.kernel._f4rows",
                             ["kernel/_f4rows.c", "kernel/_f4sym.c", "kernel/_f4pairs.c", "kernel/_f4lift.c"],
                             depends=["kernel/_intmath.h"], optional=True, extra_compile_args=["-O2"]),
                   Extension("mech.kernel._fglm", ["kernel/_fglm.c", "kernel/_fglm_proof.c"],
                             depends=["kernel/_intmath.h"], optional=True, extra_compile_args=["-O2"]),
                   Extension("mech.kernel._bba", ["kernel/_bba.c"], depends=["kernel/_intmath.h"], optional=True,
                             extra_compile_args=["-O2"]),
                   Extension("mech.kernel._mora", ["kernel/_mora.c"], depends=["kernel/_mora_poly.h"], optional=True,
                             extra_compile_args=["-O2"])])
