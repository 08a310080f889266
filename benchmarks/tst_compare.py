"""Comparing mech's output of a script with Singular's, as text and, where the text differs, as values.

Both outputs are parsed into items: text lines, ideals (``name[i]=...`` lines), matrices
(``name[i,j]=...``) and lists (``[i]:`` headers with their elements indented by three).  Items are
compared in order; ideals whose text differs are compared as ideals (modules as modules), lists of ideal-valued elements as
sets, primary decompositions (lists of [Q, P] pairs) up to the choice of embedded components, and
factorizations (an ideal of factors with their multiplicities) up to order and constant factors.  The
algebraic questions this raises are answered by an :class:`Oracle` (Singular, in the runner).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Callable, Optional

from tst_source import MARKER

#: A ring as Singular's markers give it: (string(basering), string(minpoly), string(ideal(basering))).
Ring = tuple[str, str, str]

_LIST_HEAD = re.compile(r"\[(\d+)\]:$")
#: a line ``echo`` prints (``FILE  LINE> text``): the script's text, its file name and lines differ
_ECHO = re.compile(r"^\S+ +\d+[>.](?: |$)")
_GEN = re.compile(r"([A-Za-z_@][\w@]*)\[(\d+)\]=(.*)$")
_ENTRY = re.compile(r"([A-Za-z_@][\w@]*)\[(\d+),(\d+)\]=(.*)$")
_ERROR = re.compile(r"^\s*\? ")


@dataclass
class Item:
    """One printed value."""

    kind: str                  # "text", "ideal", "matrix", "list"
    line: int                  # its first line in the output (1-based)
    ring: Optional[Ring] = None
    text: str = ""             # a text line; the name of an ideal or matrix
    gens: list[str] = field(default_factory=list)          # generators; matrix entries "i,j=..."
    elems: list[list["Item"]] = field(default_factory=list)  # list elements

    def show(self) -> str:
        if self.kind == "text":
            s = self.text
        elif self.kind == "list":
            s = f"list of {len(self.elems)}"
        else:
            s = f"{self.text}: " + ", ".join(self.gens)
        return s if len(s) <= 90 else s[:87] + "..."


# ---------------------------------------------------------------- parsing
def split_error(output: str) -> tuple[str, Optional[str]]:
    """Singular's output up to its first error, and that error's message (None without error)."""
    lines = output.splitlines()
    for k, line in enumerate(lines):
        if _ERROR.match(line):
            return "\n".join(lines[:k]), line.strip()[2:]
    return output, None


def normalize(output: str) -> str:
    """The text compared exactly: trailing blanks, blank lines, ``// **`` notes, markers and the lines
    ``echo`` prints dropped."""
    keep = [ln.rstrip() for ln in output.splitlines() if not _ECHO.match(ln)]
    return "\n".join(ln for ln in keep if ln and not ln.lstrip().startswith("// **") and not ln.startswith(MARKER))


def parse(output: str) -> list[Item]:
    """The items of an output; marker lines (Singular's) set the ring of the items after them."""
    lines: list[tuple[int, Optional[Ring], str]] = []
    ring: Optional[Ring] = None
    for no, raw in enumerate(output.splitlines(), 1):
        line = raw.rstrip()
        if line.startswith(MARKER):
            ring = tuple((line[len(MARKER):].split("@@") + ["0", "0"])[:3])
        elif _ECHO.match(line):
            continue
        elif line and not line.lstrip().startswith("// **"):
            lines.append((no, ring, line))
    pos = 0

    def indent(text: str) -> int:
        return len(text) - len(text.lstrip(" "))

    def block(level: int) -> list[Item]:
        nonlocal pos
        items: list[Item] = []
        while pos < len(lines):
            no, ring, text = lines[pos]
            if indent(text) < level:
                break
            body = text[level:]
            if indent(text) == level and _LIST_HEAD.match(body):
                elems: list[list[Item]] = []
                while pos < len(lines) and indent(lines[pos][2]) == level:
                    head = _LIST_HEAD.match(lines[pos][2][level:])
                    if not head or (elems and head.group(1) == "1"):  # [1]: starts the next list
                        break
                    pos += 1
                    elems.append(block(level + 3))
                items.append(Item("list", no, ring, elems=elems))
                continue
            m = _GEN.match(body) if indent(text) == level else None
            if m and m.group(2) == "1":
                gens = [m.group(3)]
                pos += 1
                while pos < len(lines):
                    m2 = _GEN.match(lines[pos][2][level:]) if indent(lines[pos][2]) == level else None
                    if not m2 or m2.group(1) != m.group(1) or int(m2.group(2)) != len(gens) + 1:
                        break
                    gens.append(m2.group(3))
                    pos += 1
                items.append(Item("ideal", no, ring, text=m.group(1), gens=gens))
                continue
            m = _ENTRY.match(body) if indent(text) == level else None
            if m:
                entries = []
                while pos < len(lines):
                    m2 = _ENTRY.match(lines[pos][2][level:]) if indent(lines[pos][2]) == level else None
                    if not m2 or m2.group(1) != m.group(1) or (entries and m2.group(2, 3) == ("1", "1")):
                        break  # [1,1] starts the next matrix
                    entries.append(f"{m2.group(2)},{m2.group(3)}={m2.group(4)}")
                    pos += 1
                items.append(Item("matrix", no, ring, text=m.group(1), gens=entries))
                continue
            items.append(Item("text", no, ring, text=body))
            pos += 1
        return items

    return block(0)


# ---------------------------------------------------------------- the oracle
Question = tuple  # (kind, ring, *texts): "eq" A B, "sub" A B, "inter_eq" As Bs, "primary" Q P, "poly_eq" f g


class Oracle:
    """Answers of algebraic questions; unknown ones are recorded (and assumed true for this pass)."""

    def __init__(self, answer: Callable[[list[Question]], dict[Question, bool]]) -> None:
        self.answer = answer
        self.known: dict[Question, bool] = {}
        self.pending: set[Question] = set()

    def ask(self, q: Question) -> bool:
        if q in self.known:
            return self.known[q]
        self.pending.add(q)
        return True

    def settle(self) -> bool:
        """Answer the pending questions; False when there were none."""
        if not self.pending:
            return False
        qs = sorted(self.pending, key=repr)
        got = self.answer(qs)
        for q in qs:
            self.known[q] = got.get(q, False)
        self.pending.clear()
        return True


def compare(singular: list[Item], mech: list[Item], oracle: Oracle, rounds: int = 6) -> Optional[str]:
    """None when the outputs agree as values, else the first difference; the oracle is consulted
    (and settled) until no question is open."""
    for _ in range(rounds):
        why = _same_seq(singular, mech, None, oracle)
        if not oracle.settle():
            return why
    return _same_seq(singular, mech, None, oracle)


def _same_seq(S: list[Item], M: list[Item], ring: Optional[Ring], o: Oracle) -> Optional[str]:
    for s, m in zip(S, M):
        why = _same(s, m, s.ring or ring, o)
        if why:
            return why
    if len(S) > len(M):
        return f"output line {S[len(M)].line}: Singular prints `{S[len(M)].show()}`, mech nothing more"
    if len(M) > len(S):
        return f"mech prints `{M[len(S)].show()}` where Singular's output ends"
    return None


def _same(s: Item, m: Item, ring: Optional[Ring], o: Oracle) -> Optional[str]:
    where = f"output line {s.line}: Singular `{s.show()}` / mech `{m.show()}`"
    if s.kind != m.kind:
        return where
    if s.kind in ("text", "matrix"):
        return None if (s.text, s.gens) == (m.text, m.gens) else where
    if s.kind == "ideal":
        if s.text != m.text:
            return where + " (printed name)"
        return None if _ideal_eq(s.gens, m.gens, ring, o) else where
    if len(s.elems) == len(m.elems) and all(_same_seq(a, b, ring, o) is None for a, b in zip(s.elems, m.elems)):
        return None
    reasons = []
    for rule in (_as_set, _as_primdec, _as_factors):
        verdict = rule(s.elems, m.elems, ring, o)
        if verdict == "":
            return None
        if verdict is not None:
            reasons.append(verdict)
    return f"{where}: {reasons[-1]}" if reasons else _same_seq_list(s, m, ring, o)  # the most specific


def _same_seq_list(s: Item, m: Item, ring: Optional[Ring], o: Oracle) -> Optional[str]:
    for k, (a, b) in enumerate(zip(s.elems, m.elems), 1):
        why = _same_seq(a, b, ring, o)
        if why:
            return f"list element [{k}]: {why}"
    return f"output line {s.line}: Singular's list has {len(s.elems)} elements, mech's {len(m.elems)}"


def _ideal_eq(a: list[str], b: list[str], ring: Optional[Ring], o: Oracle) -> bool:
    if a == b:
        return True
    return ring is not None and o.ask(("eq", ring, tuple(a), tuple(b)))


# ---------------------------------------------------------------- non-unique results
def _ideal_valued(elem: list[Item]) -> bool:
    return len(elem) == 1 and (elem[0].kind == "ideal" or elem[0].kind == "list" and
                               all(_ideal_valued(e) for e in elem[0].elems))


def _as_set(S: list[list[Item]], M: list[list[Item]], ring: Optional[Ring], o: Oracle) -> Optional[str]:
    """Lists of ideal-valued elements as multisets: "" when they agree, a reason when not, None when
    the rule does not apply."""
    if not S or not all(map(_ideal_valued, S + M)):
        return None
    if len(S) != len(M):
        return f"{len(S)} elements in Singular's list, {len(M)} in mech's"
    eq = [[_same_seq(a, b, ring, o) is None for b in M] for a in S]
    return "" if _perfect_matching(eq) else "the elements differ (compared as a set)"


def _perfect_matching(eq: list[list[bool]]) -> bool:
    match: dict[int, int] = {}

    def augment(i: int, seen: set[int]) -> bool:
        for j, ok in enumerate(eq[i]):
            if ok and j not in seen:
                seen.add(j)
                if j not in match or augment(match[j], seen):
                    match[j] = i
                    return True
        return False
    return all(augment(i, set()) for i in range(len(eq)))


def _pairs(L: list[list[Item]]) -> Optional[list[tuple[list[str], list[str]]]]:
    out = []
    for e in L:
        if len(e) != 1 or e[0].kind != "list" or len(e[0].elems) != 2:
            return None
        q, p = e[0].elems
        if len(q) != 1 or len(p) != 1 or q[0].kind != "ideal" or p[0].kind != "ideal":
            return None
        out.append((q[0].gens, p[0].gens))
    return out


def _as_primdec(S: list[list[Item]], M: list[list[Item]], ring: Optional[Ring], o: Oracle) -> Optional[str]:
    """Primary decompositions: the same associated primes, the same isolated components, the same
    intersection, and each of mech's embedded components primary to its prime."""
    sp, mp = _pairs(S), _pairs(M)
    if not sp or not mp or ring is None:
        return None
    primes_s, primes_m = [p for _, p in sp], [p for _, p in mp]
    eq = [[_ideal_eq(a, b, ring, o) for b in primes_m] for a in primes_s]
    if len(sp) != len(mp) or not _perfect_matching(eq):
        return "different associated primes"
    for i, (q, p) in enumerate(sp):
        isolated = not any(k != i and o.ask(("sub", ring, tuple(p2), tuple(p))) and not _ideal_eq(p2, p, ring, o)
                           for k, (_, p2) in enumerate(sp))
        if not isolated:
            continue
        if not any(_ideal_eq(p, p2, ring, o) and _ideal_eq(q, q2, ring, o) for q2, p2 in mp):
            return "different isolated primary component"
    if not o.ask(("inter_eq", ring, tuple(map(tuple, (q for q, _ in sp))), tuple(map(tuple, (q for q, _ in mp))))):
        return "the intersection of the components differs"
    for q, p in mp:
        if not o.ask(("primary", ring, tuple(q), tuple(p))):
            return "a component of mech's is not primary to its prime"
    return ""


def _as_factors(S: list[list[Item]], M: list[list[Item]], ring: Optional[Ring], o: Oracle) -> Optional[str]:
    """Factorizations [ideal of factors, multiplicities]: the same product, the same non-constant
    factors up to constants with the same multiplicities."""
    fs, fm = _factors(S), _factors(M)
    if fs is None or fm is None or ring is None:
        return None

    def product(fac: list[tuple[str, int]]) -> str:
        return "*".join(f"({f})^{e}" for f, e in fac)
    if not o.ask(("poly_eq", ring, product(fs), product(fm))):
        return "different products"
    nonconst = [[(f, e) for f, e in fac if re.search(r"[A-Za-z]", f)] for fac in (fs, fm)]
    eq = [[e1 == e2 and _ideal_eq([f1], [f2], ring, o) for f2, e2 in nonconst[1]] for f1, e1 in nonconst[0]]
    if len(nonconst[0]) != len(nonconst[1]) or not _perfect_matching(eq):
        return "different factors"
    return ""


def _factors(L: list[list[Item]]) -> Optional[list[tuple[str, int]]]:
    if len(L) != 2 or len(L[0]) != 1 or len(L[1]) != 1 or L[0][0].kind != "ideal" or L[1][0].kind != "text":
        return None
    gens, mult = L[0][0].gens, L[1][0].text.split(",")
    if len(gens) != len(mult) or not all(x.strip().isdigit() for x in mult):
        return None
    return list(zip(gens, (int(x) for x in mult)))


# ---------------------------------------------------------------- the questions, in Singular
def _names(decl: str) -> set[str]:
    """The variables and parameters of a ring declaration ``(0,a),(x,y),(dp(2),C)``."""
    depth, parts, start = 0, [], 0
    for k, ch in enumerate(decl):
        depth += (ch == "(") - (ch == ")")
        if ch == "," and depth == 0:
            parts.append(decl[start:k])
            start = k + 1
    parts.append(decl[start:])
    char = parts[0].strip("()").split(",")[1:]
    return {n.strip() for n in char + (parts[1].strip("()").split(",") if len(parts) > 1 else [])}


def long_form(text: str, names: set[str]) -> str:
    """A polynomial printed in Singular's short form (``2ab2``) in the long form (``2*a*b^2``), when all
    names are single letters; Singular reads the short form back wrongly where letters spell a keyword
    (``def``)."""
    if not all(len(n) == 1 for n in names):
        return text

    def word(m: re.Match) -> str:
        w = m.group(0)
        coef, mono = re.match(r"(\d*)(.*)", w).groups()
        factors = re.findall(r"([A-Za-z])(\d*)", mono)
        if "".join(a + e for a, e in factors) != mono or not all(a in names for a, _ in factors):
            return w
        return "*".join(([coef] if coef else []) + [a + (f"^{e}" if e else "") for a, e in factors])
    return re.sub(r"(?<![\w^])\d*[A-Za-z][A-Za-z0-9]*", word, text)


def check_script(questions: list[Question]) -> str:
    """A Singular script printing ``@@ANS k 0|1`` for each question (no line: it could not be decided)."""
    out = ['LIB "primdec.lib";'] if any(q[0] == "primary" for q in questions) else []
    for k, q in enumerate(questions):
        kind, (decl, minpoly, quotient) = q[0], q[1]
        names = _names(decl)
        minpoly, quotient = long_form(minpoly, names), long_form(quotient, names)
        q = q[:2] + tuple(_convert(x, names) for x in q[2:])
        out.append(f"ring R@{k} = {decl};")
        if minpoly not in ("0", ""):
            out.append(f"minpoly = {minpoly};")
        if quotient not in ("0", ""):
            out.append(f"ideal Q@{k} = {quotient}; qring S@{k} = std(Q@{k});")
        a, b = q[2], q[3]
        if kind == "poly_eq":
            out.append(f"int r@{k} = (({a}) - ({b}) == 0);")
        elif kind == "primary":
            out.append(f"list L@{k} = primdecGTZ(ideal({', '.join(a)})); ideal P@{k} = {', '.join(b)};")
            out.append(f"int r@{k} = (size(L@{k}) == 1); if (r@{k}) {{ r@{k} = "
                       f"(size(reduce(P@{k}, std(L@{k}[1][2]))) + size(reduce(L@{k}[1][2], std(P@{k}))) == 0); }}")
        else:
            if kind == "inter_eq":
                a_def = " ".join(f"A@{k} = intersect(A@{k}, ideal({', '.join(g)}));" for g in a[1:])
                b_def = " ".join(f"B@{k} = intersect(B@{k}, ideal({', '.join(g)}));" for g in b[1:])
                out.append(f"ideal A@{k} = {', '.join(a[0])}; {a_def} ideal B@{k} = {', '.join(b[0])}; {b_def}")
            else:  # generators of submodules (vectors) are compared as modules
                typ = "module" if any("gen(" in g or g.startswith("[") for g in a + b) else "ideal"
                out.append(f"{typ} A@{k} = {', '.join(a)}; {typ} B@{k} = {', '.join(b)};")
            test = f"size(reduce(A@{k}, std(B@{k}))) == 0"
            if kind != "sub":
                test = f"({test}) && (size(reduce(B@{k}, std(A@{k}))) == 0)"
            out.append(f"int r@{k} = {test};")
        out.append(f'"@@ANS {k} " + string(r@{k});')
    return "\n".join(out) + "\n"


def _convert(x, names: set[str]):
    if isinstance(x, str):
        return long_form(x, names)
    return tuple(_convert(y, names) for y in x) if isinstance(x, tuple) else x


def read_answers(questions: list[Question], output: str) -> dict[Question, bool]:
    got = {}
    for m in re.finditer(r"^@@ANS (\d+) ([01])$", output, re.M):
        got[questions[int(m.group(1))]] = m.group(2) == "1"
    return got
