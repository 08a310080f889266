"""The commands of ``LIB "mechanism.lib";`` on a mechanism's analysis: its ring, constraints,
mobility, motion modes, singular variety and configurations, length conditions, and ``analyze``
(the report, in a format of :data:`mech.stdlib.reports.FORMATS`).  The pictures are in
:mod:`mech.stdlib.plots`."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Sequence

from mech.dsl.convert import parse_decimal
from mech.dsl.errors import MechRuntimeError
from mech.dsl.registry import command
from mech.dsl.values import Ideal, List, Ring
from mech.kernel import Poly
from mech.stdlib.analysis import Analysis, require_complete, require_numeric, run_analysis
from mech.stdlib.mechanism import Mechanism, MechanismError
from mech.stdlib.reports import FORMATS, dp_basis, unknown_format


def _into(ctx: Any, polys: Sequence[Poly]) -> Ideal:
    """The polynomials as an ideal of the basering (mapped by variable names)."""
    from mech.kernel.maps import imap
    ring = ctx.basering().poly
    if not polys:
        return Ideal(ring, [])
    missing = [n for g in polys for i, n in enumerate(g.ring.names)
               if n not in ring.names and any(e[i] for e in g.terms)]
    if missing:
        raise MechRuntimeError(f"the basering lacks the mechanism's variable {missing[0]} "
                               "(def r = configurationRing(m); setring r;)")
    return Ideal(ring, imap(list(polys), polys[0].ring, ring))


def _complete(a: Analysis, what: str) -> Analysis:
    require_complete(a, what)
    return a


@command("setLengths", lib="mechanism.lib")
def set_lengths(m: Mechanism, *values: int | str) -> Mechanism:
    """setLengths(m, v1, v2, ...): m with its symbolic lengths (in order of appearance) set to the
    values (integers or strings "p/q").

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      setLengths(m, 2, "1/2");
      → fix O 0 0; bar O A 2; bar A B 1/2; slider B
    """
    names = m.symbols()
    if len(values) != len(names):
        raise MechRuntimeError(f"setLengths: the mechanism has {len(names)} symbolic lengths "
                               f"({','.join(names)}), {len(values)} values given")
    vals: dict[str, Any] = {}
    for n, v in zip(names, values):
        try:
            vals[n] = parse_decimal(v) if isinstance(v, str) else v
        except ValueError as e:
            raise MechRuntimeError(f"setLengths: {e}") from None
    return m.with_values(vals)


@command("lengths", lib="mechanism.lib")
def lengths(m: Mechanism) -> List:
    """lengths(m): the names of the symbolic lengths, in order of appearance.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      lengths(m);
      → [1]:
      →    l1
      → [2]:
      →    l2
    """
    return List(m.symbols())


@command("configurationRing", lib="mechanism.lib")
def configuration_ring(m: Mechanism) -> Ring:
    """configurationRing(m): the ring 0,(c1,s1,...,lengths),(dp(n),dp(k)) of the constraints.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      def r = configurationRing(m); r;
      → // coefficients: QQ
      → // number of vars : 6
      → //        block   1 : ordering dp
      → //                  : names    c1 s1 c2 s2
      → //        block   2 : ordering dp
      → //                  : names    l1 l2
    """
    from mech.dsl.rings import make_ring
    from mech.dsl.values import OrderBlock
    n, params = len(m.variables()), list(m.symbols())
    blocks = [OrderBlock("dp", n)] + ([OrderBlock("dp", len(params))] if params else [])
    return make_ring(0, (), m.variables() + params, blocks)


@command("constraints", lib="mechanism.lib")
def constraints(ctx: Any, m: Mechanism) -> Ideal:
    """constraints(m): the constraint ideal J (loop and slider constraints, then the circles).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      def r = configurationRing(m); setring r;
      constraints(m);
      → _[1]=s1*l1+s2*l2
      → _[2]=c1^2+s1^2-1
      → _[3]=c2^2+s2^2-1
    """
    try:
        return _into(ctx, m.constraints()[1])
    except MechanismError as e:
        raise MechRuntimeError(str(e)) from None


@command("mobility", lib="mechanism.lib")
def mobility(m: Mechanism) -> int:
    """mobility(m): the dimension of the configuration space (for generic symbolic lengths).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      mobility(m);
      → 1
    """
    return _complete(run_analysis(m, local=False), "mobility").mobility


@command("motionModes", lib="mechanism.lib")
def motion_modes(ctx: Any, m: Mechanism) -> List:
    """motionModes(m): the prime components of J, each as list(prime, dim, has real points).
    With symbolic lengths: the modes over Q(lengths) (the generic mechanism's), with their
    dimension over Q(lengths) and -1 for real points (not decided); an error when they could not
    be certified (see docs/mechanisms.md, Limits).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 1; slider B";
      def r = configurationRing(m); setring r;
      list L = motionModes(m);
      size(L); L[1][1]; L[1][2]; L[1][3];
      → 2
      → _[1]=s1+s2
      → _[2]=c1-c2
      → _[3]=c2^2+s2^2-1
      → 1
      → 1
    """
    a = _complete(run_analysis(m, local=False), "motionModes")
    if not a.modes_found:
        raise MechRuntimeError("motionModes: no strategy found the motion modes within its budget "
                               "(analyze(m) shows what was found)")
    if a.params and not a.modes:
        raise MechRuntimeError(f"motionModes: the modes over Q({','.join(a.params)}) were not certified "
                               "(no sparse birational projection, or too many variables): give numeric "
                               "lengths (setLengths(m, ...))")
    return List([List([_into(ctx, dp_basis(md.prime)), md.dim, -1 if md.real is None else int(md.real)])
                 for md in a.modes])


@command("singularVariety", lib="mechanism.lib")
def singular_variety(ctx: Any, m: Mechanism) -> Ideal:
    """singularVariety(m): J + I_r(dJ), the Fitting ideal of Theorem 1 added to J.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      def r = configurationRing(m); setring r;
      size(singularVariety(m));
      → 7
    """
    a = _complete(run_analysis(m, local=False), "singularVariety")
    return _into(ctx, list(a.ideal) + a.fitting)


@command("lengthConditions", lib="mechanism.lib")
def length_conditions(ctx: Any, m: Mechanism) -> Ideal:
    """lengthConditions(m): the irreducible factors on the lengths, one of which must vanish
    for singular configurations to exist.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
      def r = configurationRing(m); setring r;
      lengthConditions(m);
      → _[1]=l1-l2
      → _[2]=l1+l2
    """
    a = _complete(run_analysis(m, local=False, decompose=False), "lengthConditions")  # without the modes
    if not a.params:
        raise MechRuntimeError("lengthConditions needs symbolic lengths")
    return _into(ctx, a.length_factors)


@command("singularPoints", lib="mechanism.lib")
def singular_points(ctx: Any, m: Mechanism) -> List:
    """singularPoints(m): each singular configuration as list(prime, kind, tangent cone,
    local components, transition) (cone and components centred at the point; at a point with
    algebraic coordinates they have coefficients in Q(t), which analyze prints: here an empty
    ideal and list).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 1; slider B";
      def r = configurationRing(m); setring r;
      list S = singularPoints(m);
      size(S); S[1][1]; S[1][2]; S[1][3];
      → 2
      → _[1]=s2+1
      → _[2]=c2
      → _[3]=s1-1
      → _[4]=c1
      → components meet
      → _[1]=s2
      → _[2]=s1
      → _[3]=c1^2-c2^2
    """
    a = _complete(run_analysis(m), "singularPoints")
    require_numeric(a, "singularPoints")
    return List([List([_into(ctx, dp_basis(s.prime)), s.kind or "not a point",
                       _into(ctx, [] if s.algebraic else dp_basis(s.tangent_cone)),
                       List([] if s.algebraic else [_into(ctx, dp_basis(c)) for c in s.local_components]),
                       s.transition])
                 for s in a.singular])


@command("analyze", lib="mechanism.lib")
def analyze_cmd(ctx: Any, m: Mechanism, form: str = "", depth: str = "full") -> None:
    """analyze(m[, "text"|"json"|"latex"[, "full"|"quick"]]): prints the whole analysis ("quick":
    without the primary decomposition of J, so without motion modes and local components; the
    default format is text, or the one given by mech --format).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; slider A";
      analyze(m);
      → mechanism: fix O 0 0; bar O A 1; slider A
      → variables: c1,s1
      → constraint ideal J:
      →   s1
      →   c1^2+s1^2-1
      → mobility 0; J is radical
      → assembly modes (Galois orbits of configurations over Q: the irreducible factors of the separating polynomial of t = c1): 2, of 1 and 1 configurations (1 and 1 real); 2 complex configurations, 2 real
      →   [1] dim 0, has real points: <s1, c1-1>
      →       rigid mode (an isolated configuration: no link moves)
      →   [2] dim 0, has real points: <s1, c1+1>
      →       rigid mode (an isolated configuration: no link moves)
      → singular configurations: 0 (finitely many configurations, each an isolated point; the Fitting ideal and the local analysis do not apply)
      →   the Jacobian of J has full rank 2 at all 2 configurations (checked exactly on each orbit): J is reduced, no constraint singularity
      → real answers (exact real solving):
      →   assembly modes: 2 complex, 2 real
      →     [1] A = (-1.0000, 0.0000)
      →     [2] A = (1.0000, 0.0000)
    """
    form = form or ctx.settings.get("report_format", "text")
    render = FORMATS.get(form)
    if render is None:
        raise MechRuntimeError(f"analyze: {unknown_format(form)}")
    if depth not in ("full", "quick"):
        raise MechRuntimeError(f"analyze: unknown depth '{depth}' (full or quick)")
    a = run_analysis(m, decompose=depth == "full")
    text = render(a)
    if "display" in ctx.settings and form == "text":  # a notebook: the report as HTML tables too
        from mech.stdlib._report_html import report_html
        ctx.display({"text/plain": text, "text/html": report_html(a)})
    else:
        ctx.write(text)
    require_complete(a, "analyze (the report above is partial)")


@command("jointAngles", lib="mechanism.lib")
def joint_angles(m: Mechanism, config: List) -> str:
    """jointAngles(m, list(c1,s1,...)): the joint angles in degrees (and the slides of prismatic
    joints) a person reads at a configuration given by the values of the mechanism's variables
    (integers or strings such as "1/2", "0.6"), named after the joints (docs/mechanisms.md).

    Example:
      LIB "mechanism.lib";
      mechanism m = "ground O A 1; bar O B 1; bar B C 1; bar C A 1";
      jointAngles(m, list(0, 1, 1, 0, 0, -1));
      → O 90°, B -90°, C -90°, A -90°
    """
    from mech.stdlib.mechanism_display import joint_readings, readings_text
    if m.symbols():
        raise MechRuntimeError(f"jointAngles needs numeric lengths (setLengths(m, ...) for {','.join(m.symbols())})")
    names = m.variables()
    if len(config.items) != len(names):
        raise MechRuntimeError(f"jointAngles: {len(names)} values expected ({','.join(names)}), "
                               f"{len(config.items)} given")
    values: dict[str, float] = {}
    for n, v in zip(names, config.items):
        try:
            values[n] = float(parse_decimal(v)) if isinstance(v, str) else float(v)
        except (ValueError, TypeError):
            raise MechRuntimeError(f"jointAngles: '{v}' is not a number (integers or strings such as \"1/2\")") from None
    R, gens = m.constraints()
    point = {n: Fraction(values[n]) for n in names}
    bad = max(abs(float(g.evaluate([point.get(n, 0) for n in R.names]))) for g in gens)
    if bad > 1e-6:
        raise MechRuntimeError(f"jointAngles: the values are not a configuration (a constraint is {bad:.3g})")
    return readings_text(joint_readings(m, values))


@command("mechanismSyntax", lib="mechanism.lib")
def mechanism_syntax() -> str:
    """mechanismSyntax(): the statements of a mechanism's description, each form with its meaning (from
    the joint registry, stdlib/joints.py).

    Example:
      LIB "mechanism.lib";
      string h = mechanismSyntax();
      size(h) > 1000;
      → 1
    """
    from mech.stdlib.joints import syntax
    return syntax()
