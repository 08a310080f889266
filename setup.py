"""The optional compiled F4 row kernel (kernel/_f4rows.c, kernel/_f4sym.c): built when a C compiler is present,
skipped otherwise (mech then uses the pure-Python linear algebra).  Everything else is in
pyproject.toml."""
from setuptools import Extension, setup

setup(ext_modules=[Extension("mech.kernel._f4rows", ["kernel/_f4rows.c", "kernel/_f4sym.c"], optional=True,
                             extra_compile_args=["-O2"])])
