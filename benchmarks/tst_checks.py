"""Values Singular chooses among many correct ones, judged by a check Singular runs on mech's choice.

Where Singular's result is not unique (a remainder by generators that are no standard basis, the
generators of a kernel, a transformation matrix, the order of components), a case's script is edited
so that both systems print the value on a line of its own, ``@@VALUE field @@ field ...`` (the fields
are ``string(...)`` of the value and of what the check needs beside it); those lines are taken out of
both outputs, the rest is compared as usual, and then Singular runs the case's ``test`` once per value
line, in the ring that line was printed in, with ``{m1}``, ``{m2}``, ... standing for mech's fields and
``{s1}``, ... for Singular's.  The test sets ``ok`` to 1 only when it proves mech's value right; the
case agrees only when every value passes (``judge_checked``).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable, Optional

from tst_compare import MARKER, Ring, _names, long_form

VALUE = "@@VALUE "
FIELD = " @@ "


@dataclass(frozen=True)
class Check:
    """How one case's non-unique values are judged."""

    reason: str                          # what is not unique, and what the test proves of mech's value
    edits: tuple[tuple[str, str], ...]   # (text of the script, its replacement printing @@VALUE lines)
    test: str | dict[int, str]           # Singular statements setting int ok from {m1}.. and {s1}..
    #                                      (a dict: the test for each number of fields)


def value(*exprs: str) -> str:
    """A Singular statement printing ``@@VALUE`` and the strings of ``exprs`` separated by `` @@ ``."""
    return f'"{VALUE}" + ' + f' + "{FIELD}" + '.join(f"string({e})" for e in exprs) + ";"


def edit(script: str, check: Check) -> Optional[str]:
    """The script with the check's edits made (None when one of its texts is not in the script)."""
    for old, new in check.edits:
        if old not in script:
            return None
        script = script.replace(old, new)
    return script


def split_values(output: str) -> tuple[str, list[tuple[Optional[Ring], list[str]]]]:
    """The output without its ``@@VALUE`` lines, and each such line's ring (from the marker lines
    before it, Singular's) and fields."""
    kept, values = [], []
    ring: Optional[Ring] = None
    for line in output.splitlines():
        if line.startswith(MARKER):
            ring = tuple((line[len(MARKER):].split("@@") + ["0", "0"])[:3])
        if line.startswith(VALUE):
            values.append((ring, line[len(VALUE):].split(FIELD)))
        else:
            kept.append(line)
    return "\n".join(kept) + ("\n" if output.endswith("\n") else ""), values


def check_script(check: Check, singular: list, mech: list) -> str:
    """A Singular script printing ``@@OK k 0|1`` for the k-th value (mech's against Singular's)."""
    out = ['LIB "primdec.lib";']
    for k, ((ring, s_fields), (_, m_fields)) in enumerate(zip(singular, mech)):
        decl, minpoly, quotient = ring
        names = _names(decl)
        fields = {f"s{i}": long_form(t, names) for i, t in enumerate(s_fields, 1)}
        fields.update({f"m{i}": long_form(t, names) for i, t in enumerate(m_fields, 1)})
        test = _private(check.test if isinstance(check.test, str) else check.test.get(len(m_fields), ""))
        body = re.sub(r"\{([sm]\d+)\}", lambda m: fields.get(m.group(1), "UNDEFINED@"), test)
        setup = [f"ring R@{k} = {decl};"]
        if minpoly not in ("0", ""):
            setup.append(f"minpoly = {long_form(minpoly, names)};")
        if quotient not in ("0", ""):
            setup.append(f"ideal Q@{k} = {long_form(quotient, names)}; qring S@{k} = std(Q@{k});")
        out.append(f"proc check@{k}() {{ {' '.join(setup)} int ok = 0; {body} return(ok); }}")
        out.append(f'"@@OK {k} " + string(check@{k}());')
    return "\n".join(out) + "\n"


_DECLARED = re.compile(r"\b(?:poly|ideal|module|matrix|vector|int|list|number)\s+([A-Za-z]\w*)")


def _private(test: str) -> str:
    """The test with the names it declares suffixed by @: none is a variable or parameter of the ring."""
    for name in set(_DECLARED.findall(test)):
        test = re.sub(rf"(?<![\w{{@])\b{name}\b(?![@}}])", name + "@", test)
    return test


def judge_checked(check: Check, s_text: str, mech_out: str, run_singular: Callable[[str], str],
                  judge: Callable[[str, str], "object"]):
    """The case's result: ``judge`` of both outputs without their value lines; when that agrees,
    agreement holds only if Singular proves each of mech's values right (else a difference)."""
    s_rest, s_values = split_values(s_text)
    m_rest, m_values = split_values(mech_out)
    r = judge(s_rest, m_rest)
    if r.category != "agree":
        return r
    if len(s_values) != len(m_values) or any(ring is None for ring, _ in s_values):
        r.category, r.key = "differ", "value"
        r.detail = f"checked values: Singular prints {len(s_values)}, mech {len(m_values)}"
        return r
    if [f for _, f in s_values] == [f for _, f in m_values]:
        return r
    differ = [k for k in range(len(s_values)) if s_values[k][1] != m_values[k][1]]  # the same text: the same value
    script = check_script(check, [s_values[k] for k in differ], [m_values[k] for k in differ])
    answers = dict(re.findall(r"^@@OK (\d+) ([01])$", run_singular(script), re.M))
    failed = [k for n, k in enumerate(differ) if answers.get(str(n)) != "1"]
    if failed:
        k = failed[0]
        r.category, r.key = "differ", "value"
        r.detail = (f"the check of mech's value {k + 1} fails: Singular `{FIELD.join(s_values[k][1])[:80]}` / "
                    f"mech `{FIELD.join(m_values[k][1])[:80]}`")
        return r
    r.key, r.detail = "checked", check.reason
    return r


# ---------------------------------------------------------------- the tests (Singular; ok = 1: proven)
_MODULE_EQ = ("module A = {m1}; module B = {s1}; "
              "ok = (size(reduce(A, std(B))) == 0) && (size(reduce(B, std(A))) == 0);")
#: f - r in the ideal, and no term of r divisible by a leading term of the divisors (global orderings)
_REMAINDER = ("poly f = {s1}; ideal G = {s2}; poly r = {m3}; "
              "ok = (size(reduce(f - r, std(G))) == 0) && (reduce(r, std(lead(G))) == r);")
#: reduce(f, I, 1): f - r in I (in a local ordering: in the localization), the leading monomial of r
#: not in the leading ideal
_LAZY = ("poly f = {s1}; ideal I = {s2}; poly r = {m3}; ok = (size(reduce(f - r, std(I))) == 0) "
         "&& ((r == 0) || (reduce(leadmonom(r), std(lead(std(I)))) != 0));")
#: Mora's remainder of a vector by generators that are no standard basis: v - r in the module (in the
#: localization), the leading term of r not divisible by a leading term of the generators
_REMAINDER_LOCAL = ("vector v = {s1}; module M = {s2}; vector r = {m3}; "
                    "ok = (size(reduce(v - r, std(M))) == 0) "
                    "&& ((size(r) == 0) || (size(reduce(lead(r), std(lead(M)))) != 0));")
#: liftstd(i, T): sm = i*T, sm in i, and the leading terms of sm generate the leading ideal of i
_LIFT = ("ideal i = {s1}; ideal sm = {m2}; matrix T[{m3}][{m4}] = {m5}; "
         "ok = (size(module(matrix(sm) - matrix(i)*T)) == 0) && (size(reduce(lead(std(i)), std(lead(sm)))) == 0);")
#: s: syzygies of i (i*s = 0) generating all of them
_SYZ = ("ideal i = {s1}; module s = {m2}; matrix S = matrix(s, ncols(i), ncols(s)); "
        "ok = (size(module(matrix(i)*S)) == 0) && (size(reduce(syz(i), std(s))) == 0);")
#: liftstd of a module: G = A*T, G a standard basis of A's module (and S its syzygies)
_LIFT_MODULE = ("module A = {s1}; module G = {m2}; matrix T[{m3}][{m4}] = {m5}; int n = nrows(A); "
                "ok = (size(module(matrix(G, n, ncols(G)) - matrix(A)*T)) == 0) "
                "&& (size(reduce(lead(std(A)), std(lead(G)))) == 0);")
_LIFT_MODULE_SYZ = _LIFT_MODULE + (" module S = {m6}; matrix SS = matrix(S, ncols(A), ncols(S)); "
                                   "ok = ok && (size(module(matrix(A)*SS)) == 0) && (size(reduce(syz(A), std(S))) == 0);")
#: division(f, I) = (T, R, U): f*U = I*T + R, U a unit of the local ring, R's leading monomial outside the
#: leading ideal of I
_DIVISION = ("poly f = {s1}; ideal I = {s2}; matrix T[ncols(I)][1] = {m3}; ideal R = {m4}; matrix U[1][1] = {m5}; "
             "ok = (matrix(f)*U == matrix(I)*T + matrix(R)) && (jet(U[1,1], 0) != 0) "
             "&& ((R[1] == 0) || (reduce(leadmonom(R[1]), std(lead(std(I)))) != 0));")
#: division(G, I, n) = (T, R): G = I*T + R up to degree n, no leading monomial of R in the leading ideal of I
_DIVISION_UP_TO = ("ideal G = {s1}; ideal I = {s2}; matrix T[ncols(I)][ncols(G)] = {m3}; ideal R = {m4}; "
                   "int n = {s5}; int k; ok = (size(module(jet(matrix(G) - matrix(I)*T - matrix(R), n))) == 0); "
                   "for (k = 1; k <= ncols(R); k++) { if (R[k] != 0) { "
                   "if (reduce(leadmonom(R[k]), std(lead(std(I)))) == 0) { ok = 0; } } }")
#: liftstd(A, T, [S,] N): G = A*T modulo N, G in A + N with leading terms generating the leading module of
#: A + N (and S syzygies of A modulo N generating all of them: modulo(A, N))
_LIFT_RELATIVE = ("module A = {s1}; module N = {s2}; module G = {m3}; matrix T[{m4}][{m5}] = {m6}; int n = nrows(A); "
                  "module AN = A + N; ok = (size(reduce(module(matrix(G, n, ncols(G)) - matrix(A)*T), std(N))) == 0) "
                  "&& (size(reduce(G, std(AN))) == 0) && (size(reduce(lead(std(AN)), std(lead(G)))) == 0);")
_LIFT_RELATIVE_SYZ = _LIFT_RELATIVE + (" module S = {m7}; matrix SS = matrix(S, ncols(A), ncols(S)); "
                                       "ok = ok && (size(reduce(module(matrix(A)*SS), std(N))) == 0) "
                                       "&& (size(reduce(modulo(A, N), std(S))) == 0);")
#: the same element up to a nonzero constant factor (a gcd is defined up to units)
_ASSOCIATE = ("poly a = {m1}; poly b = {s1}; "
              "ok = ((a == 0) && (b == 0)) || ((a != 0) && (b != 0) && (leadcoef(b)*a == leadcoef(a)*b));")
#: a primary component (field 3: 1) or its radical (2) of Singular's decomposition ({m4}: the command)
_COMPONENT = ("ideal I = {s1}; ideal A = {m2}; list L = {s4}(I); int k; "
              "for (k = 1; k <= size(L); k++) { if (idealsEqual(A, L[k][{s3}])) { ok = 1; } }")
#: equidim's k-th part: as many parts as Singular's; the same associated primes (all of the part's
#: dimension) as Singular's k-th part, with the same primary components at the minimal primes of I (only
#: embedded components may be chosen otherwise)
_EQUIDIM = """ideal I = {s1}; ideal A = {m4}; ideal B = {s4};
if (({m2}) == ({s2})) {
  list PA = primdecGTZ(A); list PB = primdecGTZ(B); list mins = minAssGTZ(I);
  int d = dim(std(B)); int good = (dim(std(A)) == d) && (size(PA) == size(PB));
  int a; int b; int c; int found; int minimal;
  for (a = 1; a <= size(PA); a++) {
    good = good && (dim(std(PA[a][2])) == d);
    found = 0;
    for (b = 1; b <= size(PB); b++) {
      if (idealsEqual(PA[a][2], PB[b][2])) {
        minimal = 0;
        for (c = 1; c <= size(mins); c++) { if (idealsEqual(mins[c], PA[a][2])) { minimal = 1; } }
        if ((minimal == 0) || idealsEqual(PA[a][1], PB[b][1])) { found = 1; }
      }
    }
    good = good && found;
  }
  ok = good;
}"""


_EQUIDIM_EDIT = ("equidim(i);", "list E@ = equidim(i); int k@; for (k@ = 1; k@ <= size(E@); k@++) { "
                 + value("i", "size(E@)", "k@", "E@[k@]") + " }")
_MODULO = "modulo's generators are not unique: mech's are checked to generate the same module as Singular's"
_LIFTSTD = ("liftstd's standard basis and transformation matrix are not unique: mech's sm and T are checked "
            "to satisfy sm = i*T with the leading terms of sm generating the leading ideal of i, and its "
            "syzygies s to satisfy i*s = 0 and to generate syz(i)")
_LAZY_WHY = ("reduce(f, I, 1) reduces leading terms only, which leaves no unique remainder: mech's r is checked "
             "to have f - r in I and a leading monomial outside the leading ideal")

CHECKS: dict[str, Check] = {
    "Buch/Example_1_6_13.tst": Check(
        "reduce by generators that are no standard basis (Singular warns so) depends on the divisors chosen: "
        "mech's remainder r is checked to have f - r in the ideal and no term divisible by a leading term "
        "of the generators; reduce(f, S, 1) as reduce(f, I, 1)",
        (("reduce(f,G);", value("f", "G", "reduce(f,G)")),
         ("reduce(f,S,1);", value("f", "S", "reduce(f,S,1)", '"lazy"'))),
        {3: _REMAINDER, 4: _LAZY}),
    "Buch/Example_2_1_25.tst": Check(
        _MODULO + ": Hom(M, N) is modulo(D, C) with D = modulo(A, B); mech's D is checked to be the same module "
        "as Singular's and its E to generate the module modulo(D, C) of mech's D",
        (("  matrix E = modulo(D,C);\n", "  matrix E = modulo(D,C);\n  "
          + value("module(D)", "module(C)", "module(E)", "nrows(D)") + "\n"),
         ("print(Hom(M,N));", "matrix H@ = Hom(M,N);")),
        "module D = {m1}; module SD = {s1}; module C = {s2}; module E = {m3}; int n = {s4}; "
        "module K = modulo(matrix(D, n, ncols(D)), matrix(C, n, ncols(C))); "
        "ok = (size(reduce(D, std(SD))) == 0) && (size(reduce(SD, std(D))) == 0) "
        "&& (size(reduce(E, std(K))) == 0) && (size(reduce(K, std(E))) == 0);"),
    "Manual/Kernel_of_module_homomorphisms.tst": Check(
        _MODULO + ", and the printed A*C to be A times mech's C and to lie in the image of B",
        (("print(C);            // matrix of generators for the kernel\n  print(A*matrix(C));",
          value("A", "B", "module(C)", "module(A*matrix(C))")),),
        "matrix A[2][2] = {s1}; matrix B[2][2] = {s2}; module C = {m3}; module SC = {s3}; module P = {m4}; "
        "ok = (size(reduce(C, std(SC))) == 0) && (size(reduce(SC, std(C))) == 0) "
        "&& (size(module(matrix(P, 2, ncols(P)) - A*matrix(C, 2, ncols(C)))) == 0) "
        "&& (size(reduce(P, std(module(B)))) == 0);"),
    "Manual/reduce.tst": Check(
        _LAZY_WHY,
        (("reduce(3z3yx2+7y4x2+yx5+z12y2x2,j,1);",
          value("3z3yx2+7y4x2+yx5+z12y2x2", "j", "reduce(3z3yx2+7y4x2+yx5+z12y2x2,j,1)")),), _LAZY),
    "Old/normalf.tst": Check(
        "reduce of vectors by a module m that is no standard basis (Singular warns so), in a local ordering: "
        "the remainder depends on the divisors chosen; mech's r is checked to have v - r in m (in the "
        "localization) and a leading term not divisible by a leading term of m's generators",
        tuple((f"reduce({v},m);", value(v, "m", f"reduce({v},m)")) for v in ("v1", "v2", "v3")),
        _REMAINDER_LOCAL),
    "Old/syzygies.tst": Check(
        "syz's generators are not unique (under test(11) Singular leaves them unminimized, so m1*s1 has more "
        "columns): mech's s1 is checked to be syzygies of m1 generating all of them, and m1*s1 to be zero",
        (("m1*s1;", value("m1", "module(s1)", "m1*s1")),),
        "ideal g = {s1}; module s = {m2}; matrix S = matrix(s, ncols(g), ncols(s)); "
        "ok = (size(ideal({m3})) == 0) && (size(module(matrix(g)*S)) == 0) && (size(reduce(syz(g), std(s))) == 0);"),
    "LIB/elim.lib:elim": Check(
        "elim of a module in a local weighted ordering (ws): the generators of the module are not unique "
        "(Singular tail-reduces, mech's Lazard's method does not): mech's m is checked to be the same "
        "module as Singular's",
        (("show(m);", value("m")),), _MODULE_EQ),
    "Short/bug_tr661.tst": Check(
        "primdecSY lists the components in another order and the script picks L[2]: each ideal mech prints "
        "is checked to be a primary component (or the radical of one) of Singular's decomposition",
        (("rpc2;", value("I", "rpc2", "2", '"primdecSY"')), ("pc2;", value("I", "pc2", "1", '"primdecSY"')),
         ("radical(L[2][1]);", value("I", "radical(L[2][1])", "2", '"primdecSY"'))),
        _COMPONENT),
    "Short/bug_tr662.tst": Check(
        "primdecGTZ lists the components in another order and the script picks L[4]: mech's L[4][1] is "
        "checked to be a primary component of Singular's decomposition",
        (("L[4][1];", value("std(I)", "L[4][1]", "1", '"primdecGTZ"')),), _COMPONENT),
    "Short/gcdp_s.tst": Check(
        "a gcd is unique up to a constant factor (Singular prints its raw gcd, mech's is monic): each of "
        "mech's is checked to be Singular's times a nonzero constant; the normalized ones agree as text",
        (("  poly d=gcd( f, g );\n  d;", "  poly d=gcd( f, g );\n  " + value("d")),), _ASSOCIATE),
    "Short/bug_slimsyz.tst": Check(
        "lift's matrix is not unique when the generators of a1 have syzygies: mech's is checked to satisfy "
        "a1*result = a2",
        (("result;", value("a1", "a2", "result")),),
        "module A = {s1}; module B = {s2}; module L = {m3}; int n = nrows(A); "
        "ok = (size(module(matrix(A)*matrix(L, ncols(A), ncols(L)) - matrix(B, n, ncols(B)))) == 0);"),
    "Manual/division.tst": Check(
        "division in a local ordering: the quotients T, remainder R and unit U are not unique (Singular's U is "
        "mech's divided by 4 for f^2): mech's are checked to satisfy f*U = I*T + R with U a unit and R's leading "
        "monomial outside the leading ideal; division(G, I, 10)'s (T, R) to satisfy G = I*T + R up to degree 10 "
        "with no leading monomial of R in the leading ideal (Singular's R is x10+9/4y10, mech's 0)",
        (("division(f,jacob(f)); // automatic conversion: poly -> ideal\ndivision(f^2,jacob(f));",
          "list D@ = division(f,jacob(f)); " + value("f", "jacob(f)", "D@[1]", "D@[2]", "D@[3]")
          + "\nD@ = division(f^2,jacob(f)); " + value("f^2", "jacob(f)", "D@[1]", "D@[2]", "D@[3]")),
         ("division(ideal(f^2),jacob(f),10);", "D@ = division(ideal(f^2),jacob(f),10); "
          + value("ideal(f^2)", "jacob(f)", "D@[1]", "D@[2]", "10", '"up to"'))),
        {5: _DIVISION, 6: _DIVISION_UP_TO}),
    "Short/liftstd_m.tst": Check(
        "liftstd of a module: the standard basis, T and the syzygies are not unique (Singular leaves the tail "
        "of xz-yz unreduced): mech's G is checked to be A*T with leading terms generating the leading module "
        "of A, and S to be syzygies of A generating all of them; relative to a module N likewise modulo N",
        (("print(liftstd(module(A),T,S));\nprint(T);\nprint(S);",
          "module G@ = liftstd(module(A),T,S); " + value("module(A)", "G@", "nrows(T)", "ncols(T)", "T", "S")),
         ('print(liftstd(module(A),T,"std"));\nprint(T);\n',
          'G@ = liftstd(module(A),T,"std"); ' + value("module(A)", "G@", "nrows(T)", "ncols(T)", "T") + "\n"),
         ('print(liftstd(module(A),T,S,"std"));\nprint(T);\nprint(S);',
          'G@ = liftstd(module(A),T,S,"std"); ' + value("module(A)", "G@", "nrows(T)", "ncols(T)", "T", "S")),
         ("print(liftstd(A1,T,S,A2));\nprint(T);\nprint(S);",
          "G@ = liftstd(A1,T,S,A2); " + value("A1", "A2", "G@", "nrows(T)", "ncols(T)", "T", "S", '"relative"')),
         ('print(liftstd(A1,T,"std",A2));\nprint(T);',
          'G@ = liftstd(A1,T,"std",A2); ' + value("A1", "A2", "G@", "nrows(T)", "ncols(T)", "T", '"relative"')),
         ('print(liftstd(A1,T,S,"std",A2));\nprint(T);\nprint(S);',
          'G@ = liftstd(A1,T,S,"std",A2); ' + value("A1", "A2", "G@", "nrows(T)", "ncols(T)", "T", "S", '"relative"')),
         ('S=modulo(A1,A2,T,"std");\nprint(T);',  # modulo's T: the last standard basis G@ is A1*T modulo A2
          'S=modulo(A1,A2,T,"std"); ' + value("A1", "A2", "G@", "nrows(T)", "ncols(T)", "T", '"relative"')),
         ('matrix G=liftstd(A1,T1,S,"std",A2);\nprint(T1);\nprint(S);',
          'matrix G=liftstd(A1,T1,S,"std",A2); '
          + value("A1", "A2", "module(G)", "nrows(T1)", "ncols(T1)", "T1", "S", '"relative"')),
         ('S=modulo(A1,A2,T2,"std");\nprint(T2);',
          'S=modulo(A1,A2,T2,"std"); ' + value("A1", "A2", "module(G)", "nrows(T2)", "ncols(T2)", "T2", '"relative"'))),
        {5: _LIFT_MODULE, 6: _LIFT_MODULE_SYZ, 7: _LIFT_RELATIVE, 8: _LIFT_RELATIVE_SYZ}),
}
for _case in ("Manual/equidim.tst", "LIB/primdec.lib:equidim"):
    CHECKS[_case] = Check(
        "the parts of lower dimension of equidim are made of embedded components, which are not unique: "
        "each of mech's parts is checked to have the associated primes of Singular's part (all of its "
        "dimension) and Singular's primary components at the minimal primes of I",
        (_EQUIDIM_EDIT,), _EQUIDIM)
_LIFT_EDITS = {"print(T);": value("i", "sm", "nrows(T)", "ncols(T)", "T"), "print(s);": value("i", "s"),
               "matrix(i)*matrix(s);": value("i", "s", "matrix(i)*matrix(s)")}
for _case, _texts in (("Manual/liftstd.tst", ("print(T);", "print(s);")), ("Old/m85si.tst", ("print(T);",)),
                      ("Short/bug_tr186.tst", ("print(T);", "print(s);", "matrix(i)*matrix(s);"))):
    CHECKS[_case] = Check(_LIFTSTD, tuple((t, _LIFT_EDITS[t]) for t in _texts),
                          {5: _LIFT, 2: _SYZ, 3: _SYZ + " ok = ok && (size(ideal({m3})) == 0);"})
CHECKS["Old/m113si.tst"] = CHECKS["Manual/reduce.tst"]
