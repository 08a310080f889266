"""Macaulay2 functions of the dialect added in session 12 for issue 22 (subquotient modules: r*M,
M/N, M ++ N, 0_M, saturate and N : J of submodules, annihilators; quotient(f, g), f // g and f % g
of matrices, block matrices of maps, generator, genericSymmetricMatrix; mingens and trim in local
rings, frac, R.residueMap, R.maxIdeal, x_R; the LocalRings legacy functions setMaxIdeal,
localComplement, localMingens, localsyz, localModulo, localPrune, prune of a matrix;
isSupportedInZeroLocus): scripts with what Macaulay2 1.21 prints for them (``M2 --script``; the
``macaulay2`` tests check it against the installed Macaulay2).  Values Macaulay2 chooses (generators
of a quotient module, minimal generators in a local ring, f // g) are checked by what defines them,
not as text."""
from __future__ import annotations

import subprocess
import sys


from mech import Session
from tests.util import m2_case_tests

#: (name, script, what Macaulay2 prints)
CASES = [
    ("subquotients", """R = ZZ/32003[a..d];
m = ideal vars R;
M = R^1 / (a * m^2);
print toString (M / saturate 0_M)
print toString 0_M
print toString (a*R^2)
N = image matrix {{a, b}, {c, d}};
print toString (N/(a*N))
print toString (c*N)
print toString (N ++ N)
print toString (R^2 ++ R^1)
print toString ann(N/(a*N))
print(saturate(image matrix {{a*b, a*c}, {a*d, a^2}}, ideal(a)) == image matrix {{b, c}, {d, a}})
print toString ann(cokernel matrix {{a, b}, {c, d}} / (a * cokernel matrix {{a, b}, {c, d}}))
""",
     'cokernel matrix {{a, a^3, a^2*b, a^2*c, a^2*d, a*b^2, a*b*c, a*b*d, a*c^2, a*c*d, a*d^2}}\nvector {0}\nimage matrix {{a, 0}, {0, a}}\nsubquotient(matrix {{a, b}, {c, d}},matrix {{a^2, a*b}, {a*c, a*d}})\nimage matrix {{a*c, b*c}, {c^2, c*d}}\nimage matrix {{a, b, 0, 0}, {c, d, 0, 0}, {0, 0, a, b}, {0, 0, c, d}}\nR^3\nideal a\ntrue\nideal(a,b*c)\n'),
    ("quotients_generators", """print toString generator ideal(4, 6)
print toString generator image matrix {{4, 6}, {0, 0}}
S = QQ[x,y,z];
J = image vars S;
I = image symmetricPower(2, vars S);
print toString ((I ++ I) : (J ++ J))
print(((I ++ I) : x+y+z) == image matrix {{z, y, x, 0, 0, 0}, {0, 0, 0, z, y, x}})
h = quotient(gens I, gens J);
print(gens J * h == gens I)
print toString genericSymmetricMatrix(S, y, 1)
print toString generator ideal(x^2, x^2 + x*y - x*y)
print toString generator image matrix {{x, x^2}, {y, x*y}}
""",
     '2\nvector {2, 0}\nideal(z,y,x)\ntrue\ntrue\nmatrix {{y}}\nx^2\nvector {x, y}\n'),
    ("local_rings", """R = ZZ/32003[x,y,z,w,u];
RP = localRing(R, ideal "x,y,z,w");
J = promote(ideal(y*w*u-x*z, y^2*z-x*u^2, w*u^3-y*z^2, y^3*w-x^2*u), RP);
G = mingens J;
print toString(numcols G, ideal G == J)
print toString(numgens trim promote(ideal(x*y - 1, x^2), RP))
S = QQ[x,y,z,w];
I = ideal "xz-y2,yw-z2,xw-yz";
T = S_I;
K = frac(S/I);
print toString T.residueMap
print toString T.maxIdeal
print toString frac S
U = QQ[p,q];
V = localRing(U, ideal(p));
print toString ring(q_V)
print toString(q_V + p_V)
""",
     '(2,true)\n1\nmap(K,T,{x, y, z, w})\nideal(-y^2+x*z,-z^2+y*w,-y*z+x*w)\nfrac S\nV\np+q\n'),
    ("local_legacy", """R = ZZ/32003[x,y];
m = matrix {{x, y-1}, {0, x}};
print toString setMaxIdeal(ideal(x, y))
print toString localComplement m
print toString R.residueMap
S = QQ[a,b,c,d];
setMaxIdeal(ideal(a-1, b-2, c-3, d-4));
G = localMingens gens ideal(1+a, 1+b);
print toString numcols G
print(image G == image matrix {{1+a}})
T = ZZ/101[t,u,v,w];
setMaxIdeal ideal vars T;
print(T.residueMap === map(T, T, {0, 0, 0, 0}))
print(localsyz matrix "u,v2;w3,u4" == 0)
U = QQ[p,q,r];
setMaxIdeal ideal vars U;
L = localModulo(matrix {{p-1, q}}, matrix {{q, r}});
print toString numcols L
print(image matrix entries L == image matrix {{r, q, 0}, {0, -p+1, -1}})
V = ZZ/32003[e_0..e_4, Degrees => {2:{1,0}, 3:{0,1}}];
irr = intersect(ideal(e_0, e_1), ideal(e_2, e_3, e_4));
print toString isSupportedInZeroLocus_irr (V^1/irr^2)
print toString isSupportedInZeroLocus(irr, V^1/ideal(V_0))
W = QQ[a,b];
setMaxIdeal ideal gens W;
m = matrix {{a-1, a, b}, {a-1, a, b}};
print toString prune m
print toString localPrune image m
print toString localPrune coker matrix {{a-1, b}, {a, a^2}}
""",
     'ideal(x,y)\nmatrix {{0}, {1}}\nmap(R,R,{0, 0})\n1\ntrue\ntrue\ntrue\n3\ntrue\ntrue\nfalse\nmatrix {{a-1, a, b}, {a-1, a, b}}\nW^1\ncokernel matrix {{-a^3+a^2+a*b}}\n'),
    ("matrix_division", """RP = localRing(QQ[a,b,c,u,v,w], ideal(a,b,c,u,v,w));
f = matrix {{0, -9*u, u, 9*a}, {-b^2*w-w, b^2*w+w, 0, 0}, {-9*w, 0, w, 0}, {0, 0, 0, b^2*v+v}};
g = matrix {{u, -9*a, -9*u}, {0, 0, b^2*w+w}, {w, 0, 0}, {0, -b^2*v-v, 0}};
print(f % g == 0)
print(f % g == matrix {for i from 0 to numcols f - 1 list f_{i} % g})
print(g * (f // g) == f)
R = QQ[x,y];
h = matrix {{x, y}};
k = matrix {{x^2}};
print toString degrees source matrix {{h, k}}
print(matrix {{h, k}} == h | k)
""",
     'true\ntrue\ntrue\n{{1}, {1}, {2}}\ntrue\n'),
]


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES, prelude='needsPackage "LocalRings"\n')


def test_is_prime_refuted_by_a_zero_divisor() -> None:
    """MinimalPrimes' test of a non-prime ideal (codimension 3, six generators): answered at once."""
    code = """R = QQ[h,l,s,z,y,x];
J = ideal(h*l-l^2-4*l*s+h*y,6*h*s^2-6*s^2*x+l*s+l*z,3*h^2*s+3*l*s^2+3*s^2*y-3*h*s*x-2*h*s-2*h*z,3*l^3+27*l^2*s+36*l*s^2-3*h^2*y-3*l^2*y-12*h*s*y-9*l*s*y-12*s^2*y+3*h*y^2-3*l^2*x-12*l*s*x+3*h*y*x+8*h*s+8*h*z,h^3+l^2*s-h^2*x,12*l^2*s*y+60*l*s^2*y+3*h^2*y^2-12*h*s*y^2+3*l*s*y^2+12*s^2*y^2+3*s*y^3-12*l*s*y*x-3*h*y^2*x-8*h*s*y-8*l*s*y-8*h*z*y-8*l*z*y);
print toString {isPrime J, isPrime ideal(s,l,h), isPrime ideal(h^2-l^3), isPrime ideal(h*l)}
"""
    assert Session(dialect="m2").execute(code) == "{false, true, true, false}\n"


def test_commands_over_zz_in_a_later_process(tmp_path) -> None:
    """The commands exact over ZZ are marked where they are defined: a process that loads its
    modules lazily (from the registry's record written by an earlier one) takes diff over ZZ."""
    script = tmp_path / "zz.m2"
    script.write_text("R = ZZ[a,b]; print toString diff(a, a^3*b)\n")
    for _ in range(2):  # the first run may write the record, the second reads it
        out = subprocess.run([sys.executable, "-m", "mech", "--dialect", "m2", str(script)],
                             capture_output=True, text=True, timeout=120)
        assert out.stdout == "3*a^2*b\n", out.stderr
