"""The ideal toolbox through the language: eliminate, intersect, quotient, sat, radical, homog, det,
minor, hilb/degree/mult/vdim/kbase, factorize, ring maps and parameter rings.

Exact outputs are in tests/corpus/toolbox_*.sing/.out (real Singular 4.3.1 runs).  Here: the paper's
scripts, mathematical truths, the cases where Singular's basis is not fully tail-reduced (compared as
ideals), errors, and live differential tests against Singular (marker ``singular``)."""
import random
import re
from pathlib import Path

import pytest
from tests.util import ROOT, SINGULAR, error, run, run_singular

from mech import MechNameError, MechRuntimeError, MechTypeError, Session

CORPUS = ROOT / "tests" / "corpus"
PAPER = Path("/work/shared/reference/paper")
PRIMDEC = re.compile(r"minAssGTZ|primdecGTZ|tangentcone|^size\(L\)|^L;")  # commands of other modules


def same_ideal(session, a, b):
    """Whether the generator lists ``a`` and ``b`` (mech text) generate the same ideal."""
    session.execute(f"ideal A_ = {a}; ideal B_ = {b}; ideal SA_ = std(A_); ideal SB_ = std(B_);")
    return session.execute("size(reduce(A_, SB_)) == 0 && size(reduce(B_, SA_)) == 0;") == "1\n"


def blocks(output):
    """Singular's printed results as lists of generator texts (a sat list adds its exponent)."""
    out = []
    for line in output.splitlines():
        m = re.match(r"^(\s*)[\w]*\[(\d+)\]=(.*)$", line)
        if line == "[1]:":
            out.append([])
        elif m:
            if not m.group(1) and m.group(2) == "1":
                out.append([])
            out[-1].append(m.group(3))
        elif re.match(r"^\s+-?\d+$", line):
            out[-1].append(f"exponent {line.strip()}")
    return out


# ---------------------------------------------------------------- the paper
@pytest.mark.parametrize("name", ["slider2", "slider3", "fourbar"])
def test_corpus_holds_the_papers_scripts_without_primary_decomposition(name):
    if not PAPER.is_dir():
        pytest.skip("the reference runs are not available")
    paper = [line for line in (PAPER / f"{name}.sing").read_text().splitlines() if not PRIMDEC.search(line)]
    assert (CORPUS / f"toolbox_paper_{name}.sing").read_text().splitlines() == paper


def test_paper_elimination_steps():
    out = run("ring r = 0, (c1,s1,c2,s2,l1,l2), (dp(4),dp(2));"
              "ideal J = l1*s1+l2*s2, c1^2+s1^2-1, c2^2+s2^2-1;"
              "ideal S = J + ideal(c1,c2); eliminate(S, c1*s1*c2*s2);")
    assert out == "_[1]=l1^2-l2^2\n"
    out = run("ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));"
              "ideal J = l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;"
              "ideal E = eliminate(J + ideal(c1,c2,c3), c1*s1*c2*s2*c3*s3); E; factorize(E[1]);")
    assert out == ("E[1]=l1^4-2*l1^2*l2^2+l2^4-2*l1^2*l3^2-2*l2^2*l3^2+l3^4\n[1]:\n   _[1]=1\n   _[2]=-l1+l2-l3\n"
                   "   _[3]=l1+l2-l3\n   _[4]=-l1+l2+l3\n   _[5]=l1+l2+l3\n[2]:\n   1,1,1,1,1\n")


def test_fourbar_octic_has_the_eight_factors():
    s = Session()
    s.execute("ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));"
              "ideal J = l1*c1+l2*c2+l3*c3-1, l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;"
              "ideal S = J + ideal(-s2*c3+c2*s3, -s1*c3+c1*s3, -s1*c2+c1*s2);"
              "ideal E = eliminate(S, c1*s1*c2*s2*c3*s3); list F = factorize(E[1]);")
    assert s.execute("size(E); deg(E[1]); F[2];") == "1\n8\n1,1,1,1,1,1,1,1,1\n"
    factors = {g.to_str() for g in s.eval("F[1]").gens[1:]}
    assert factors == {f"{a}l1{b}l2+l3{c}1".replace("+l1", "l1") for a in "-+" for b in "-+" for c in "-+"}
    assert s.execute("poly p = F[1][1]; for (int i = 2; i <= 9; i++) { p = p * F[1][i]; } p == E[1];") == "1\n"


# ---------------------------------------------------------------- truths
def test_elimination_ideal_is_the_intersection_with_the_subring():
    s = Session()
    s.execute("ring r = 0, (t,x,y,z), dp; ideal I = x-t2-t, y-t3+1, z-t*x; ideal E = eliminate(I, t);"
              "ideal G = std(I);")
    assert s.execute("size(reduce(E, G));") == "0\n"  # E lies in I ...
    assert all(e[0] == 0 for g in s.eval("E").gens for e in g.terms)  # ... and is free of t
    # ... and is all of I meet K[x,y,z]: what an lp basis of I without t generates
    s.execute("ring l = 0, (t,x,y,z), lp; ideal G = std(imap(r, I)); ideal F;"
              "for (int i = 1; i <= size(G); i++) { if (G[i] == subst(G[i], t, 0)) { F = F + G[i]; } }"
              "setring r; ideal F = imap(l, F);")
    assert same_ideal(s, "E", "F")


def test_intersection_quotient_and_saturation_truths():
    s = Session()
    s.execute('LIB "elim.lib"; ring r = 0, (x,y,z), dp;'
              "ideal I = x2-y*z, x*y-z2, y3-x*z2; ideal J = x, y-z;"
              "ideal M = intersect(I, J); ideal Q = quotient(I, J); list L = sat(I, J);")
    assert s.execute("size(reduce(M, std(I))), size(reduce(M, std(J)));") == "0 0\n"
    assert s.execute("size(reduce(Q*J, std(I)));") == "0\n"
    k = s.eval("L[2]")
    s.execute(f"ideal Jk = J^{k}; ideal Qk = quotient(I, Jk); ideal Qk1 = quotient(I, J^{k + 1});")
    assert same_ideal(s, "Qk", "L[1]") and same_ideal(s, "Qk1", "L[1]")
    if k > 0:
        s.execute(f"ideal Qkm = quotient(I, J^{k - 1});")
        assert not same_ideal(s, "Qkm", "L[1]")


def test_factorize_multiplies_back():
    rng = random.Random(5)
    s = Session()
    for char in (0, 32003):
        s.execute(f"ring r{char} = {char}, (x,y,z), dp;")
        for _ in range(10):
            fs = ["+".join(f"{rng.choice([-3, -1, 1, 2])}*x^{rng.randint(0, 2)}*y^{rng.randint(0, 2)}"
                           f"*z^{rng.randint(0, 1)}" for _ in range(rng.randint(2, 3))) for _ in range(3)]
            f = "*".join(f"({a})^{rng.randint(1, 2)}" for a in fs)
            s.execute(f"poly f = {f}; list F = factorize(f); poly p = 1;"
                      "for (int i = 1; i <= size(F[1]); i++) { p = p * F[1][i]^F[2][i]; }")
            assert s.execute("p == f;") == "1\n", f


def test_hilbert_data_agree():
    s = Session()
    s.execute("ring r = 32003, (x,y,z), dp; ideal I = std(ideal(x3-y2z, y4-xz3, z5+x2y)); intvec h = hilb(I, 2);")
    assert s.execute("vdim(I) == size(kbase(I)); mult(I) == vdim(I);") == "1\n1\n"
    assert int(s.execute("vdim(I);")) == sum(s.eval("h").values)


def test_det_agrees_with_the_minors():
    s = Session()
    s.execute("ring r = 0, (a,b,c,d,e), dp;"
              "matrix M[5][5] = a,b,c,d,e, b,c,d,e,a, c,d,e,a,b, d,e,a,b,c, e,a,b,c,d+1;")
    assert s.execute("size(minor(M, 5)); minor(M, 5)[1] == det(M) || minor(M, 5)[1] == -det(M);") == "1\n1\n"
    # Laplace expansion along the first row by the 4 x 4 minors
    s.execute("poly L = 0; matrix S[4][4]; int i; int j; int k;"
              "for (k = 1; k <= 5; k++) { for (i = 2; i <= 5; i++) { for (j = 1; j <= 4; j++) {"
              "S[i-1,j] = M[i, j + (j >= k)]; } } L = L + (-1)^(k+1) * M[1,k] * det(S); }")
    assert s.execute("L == det(M);") == "1\n"


# ---------------------------------------------------------------- Singular's bases that are not tail-reduced
NOT_REDUCED = [
    # (statements, the command, Singular 4.3.1's printed generators)
    ("ring r = 0, (x,y,z), dp; ideal I = x2+y2+z2-1, x-y*z+3, 2*x*y-z;", "intersect(I, ideal(x,y))",
     ["9x2+3y2-yz+19x", "yz2-6xy-xz", "9xz2+6y2+yz+32x", "y2z-xy-3y", "6xyz+3x2+3y2-yz+x", "2y3+12xy+3xz-2y",
      "2xy2-yz"]),
    ("ring r = 0, (x,y,z), dp;", "quotient(ideal(x2-y, y2-z, xz), x+y)", ["z", "y2", "x2-y2-y"]),
    ("ring r = (0,a,b), (x,y,z), dp; ideal I = a*x + b*y - z, x2 - a, y*z - b;", "eliminate(I, x)",
     ["yz+(-b)", "(b2)*y2+(-2b)*yz+z2+(-a3)", "z3+(b3)*y+(-a3-2b2)*z"]),
]


@pytest.mark.parametrize("setup, call, singular", NOT_REDUCED)
def test_same_ideal_as_singular_with_a_reduced_basis(setup, call, singular):
    s = Session()
    s.execute(setup + f"ideal R = {call};")
    assert len(s.eval("R").gens) == len(singular)
    assert same_ideal(s, "R", ", ".join(singular))


# ---------------------------------------------------------------- operators
def test_ideal_operators():
    out = run("ring r = 0, (x,y,z), dp; ideal J = x2, xy, y3; ideal K = x, y2; J + K; J * K; J^3;")
    assert out.split("\n")[:5] == ["_[1]=x2", "_[2]=xy", "_[3]=y3", "_[4]=x", "_[5]=y2"]
    assert out.split("\n")[5:10] == ["_[1]=x3", "_[2]=x2y2", "_[3]=x2y", "_[4]=xy3", "_[5]=y5"]
    assert out.split("\n")[10:13] == ["_[1]=x6", "_[2]=x5y", "_[3]=x4y3"]


def test_ideal_operators_compactify_as_singular():
    out = run("ring r = 0, (x,y,z), dp; ideal(x, 1) + ideal(y); ideal(x, 2x, y) * ideal(2y, x);")
    assert out == "_[1]=1\n_[1]=2xy\n_[2]=x2\n_[3]=2y2\n"


# ---------------------------------------------------------------- errors
def test_errors_underline_the_call():
    e = error("ring r = 0, (x,y), dp;\nmatrix M[2][3];\npoly d = det(M) + 1;", MechRuntimeError)
    assert e.format() == ("<string>:3:10: error: det of a 2 x 3 matrix: the matrix must be square\n"
                          "poly d = det(M) + 1;\n         ^~~~~~\n")
    e = error("ring r = 0, (x,y), dp; ideal I = eliminate(x);", MechTypeError)
    assert e.message == "wrong arguments for eliminate: got (poly), expected eliminate(ideal, poly) or " \
                        "eliminate(ideal, intvec) or eliminate(module, poly)"
    assert e.format().splitlines()[2] == " " * 33 + "^" + "~" * 11
    assert "expected minor(matrix, int)" in error('ring r = 0, x, dp; minor(x, "a");', MechTypeError).message
    assert "expected factorize(poly, [int])" in error("ring r = 0, x, dp; factorize(ideal(x));").message
    assert "0, 1, 2 or 3" in error("ring r = 0, x, dp; factorize(x, 5);").message
    assert "must be 1 or 2" in error("ring r = 0, x, dp; hilb(std(ideal(x)), 3);").message
    assert "ring variable" in error("ring r = 0, (x,y), dp; homog(ideal(x), x+y);").message


def test_errors_of_rings_and_libraries():
    e = error("ring r = 0, (x,y), dp; sat(ideal(x), ideal(y));", MechNameError)
    assert 'load it with LIB "elim.lib";' in e.message
    e = error('LIB "elim.lib"; ring r = 0, (x,y), ds; sat(ideal(x), ideal(y));')
    assert "global ordering" in e.message
    assert "not available over the coefficient field QQ(a)" in error(
        "ring r = (0,a), (x,y), dp; quotient(ideal(x2, a*x*y), ideal(x));").message


def test_maps_between_incompatible_rings():
    src = "ring u = (0,p), (x,y), dp; poly g = p*x + y;\nring v = 0, (x,y), dp;\n"
    e = error(src + "map m = u, x, y;\nm(g);")
    assert e.format() == ("<string>:4:1: error: cannot map from the coefficient field QQ(p) to QQ\n"
                          "m(g);\n^~~~\n")
    assert run(src + "imap(u, g); fetch(u, g);") == "y\ny\n"  # imap and fetch send p to 0, as Singular
    assert run(src + "ring w = 0, (x,y,p), dp; imap(u, g);") == "xp+y\n"
    e = error("ring q = 0, (x,y), dp; poly h = x/7 + y; ring r7 = 7, (x,y), dp;\nimap(q, h);")
    assert "denominator is divisible by 7" in e.message and e.line == 2


def test_division_by_zero_in_arguments():
    e = error("ring r = 0, (x,y), dp;\nideal E = eliminate(ideal(x/0), y);")
    assert e.message == "division by 0" and (e.line, e.column) == (2, 27)


# ---------------------------------------------------------------- live comparisons with Singular
def _random_script(rng, char):
    vs = "xyzw"

    def lin():
        return "+".join(f"({rng.choice([-2, -1, 1, 2, 3])})*{v}" for v in rng.sample(vs, rng.randint(1, 3))) \
            + f"+({rng.randint(-2, 2)})"

    def ideal():
        kind = rng.randrange(3)
        if kind == 0:
            return f"ideal({lin()},{lin()})"
        if kind == 1:
            return f"ideal(({lin()})*({lin()}),({lin()})*({lin()}))"
        return "ideal(" + ",".join("*".join(f"{v}^{rng.randint(0, 3)}" for v in vs) for _ in range(3)) + ")"
    lines = ['LIB "elim.lib";', f"ring r = {char}, (x,y,z,w), dp;"]
    for i in range(24):
        a, b = ideal(), ideal()
        lines.append([f"eliminate({a}+{b}, {rng.choice(['x', 'y', 'x*y', 'x*z', 'w'])});",
                      f"intersect({a}, {b});", f"quotient({a}*{b}, {b});",
                      f"sat(intersect({a}, {b}), ideal({rng.choice(vs)}));"][i % 4])
    return "\n".join(lines)


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
@pytest.mark.parametrize("char", [0, 32003])
def test_live_ideal_operations_give_singulars_ideals(char):
    script = _random_script(random.Random(char + 1), char)
    theirs, ours = blocks(run_singular(script)), blocks(Session().execute(script))
    assert len(theirs) == len(ours)
    s = Session()
    s.execute(f"ring r = {char}, (x,y,z,w), dp;")
    for a, b in zip(theirs, ours):
        if a == b:
            continue
        assert [g for g in a if g.startswith("exponent")] == [g for g in b if g.startswith("exponent")]
        gens = [", ".join(g for g in x if not g.startswith("exponent")) for x in (a, b)]
        assert len(a) == len(b) and same_ideal(s, *gens)


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
@pytest.mark.parametrize("ring", ["0, (x,y,z,w), dp", "32003, (x,y,z,w), dp", "0, (x,y,z,w), ds",
                                  "7, (w,z,y,x), lp"])
def test_live_factorize_prints_as_singular(ring):
    rng = random.Random(hash(ring) % 1000)
    vs = "xyzw"

    def poly():
        if rng.random() < 0.3:  # homogeneous factors take factory's dehomogenizing path
            d = rng.randint(1, 2)
            return "+".join(f"({rng.choice([-2, -1, 1, 3])})*" + "*".join(rng.choice(vs) for _ in range(d))
                            for _ in range(rng.randint(1, 3)))
        return "+".join(f"({rng.choice([-3, -1, 1, 2])})*" + "*".join(f"{v}^{rng.randint(0, 2)}" for v in vs)
                        for _ in range(rng.randint(2, 3)))
    lines = [f"ring r = {ring};"]
    for _ in range(25):
        lines.append("factorize(" + "*".join(f"({poly()})^{rng.choice([1, 1, 2])}" for _ in range(3)) + ");")
    script = "\n".join(lines)
    assert Session().execute(script) == run_singular(script)


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_live_minors_and_hilbert_data_print_as_singular():
    rng = random.Random(9)
    lines = ["ring r = 0, (x,y,z), dp;"]
    for k in range(6):
        n, m = rng.randint(2, 4), rng.randint(2, 4)
        entries = ",".join(rng.choice(["x", "y", "z", "x+y", "2z-1", "xy", "0", "3", "y2-x"]) for _ in range(n * m))
        lines.append(f"matrix M{k}[{n}][{m}] = {entries}; minor(M{k}, 2); minor(M{k}, {min(n, m)});")
        if n == m:
            lines.append(f"det(M{k});")
        lines.append(f"ideal I{k} = std(minor(M{k}, 2)); hilb(I{k}); vdim(I{k}); kbase(I{k}); degree(I{k});")
    script = "\n".join(lines)
    assert Session().execute(script) == run_singular(script)
