"""Spatial loops of joints given by Denavit–Hartenberg parameters: their variables and equations.

Joint ``J`` of a loop moves by ``T_J = Rz(theta_J) Tz(d) Tx(a) Rx(twist)``: a revolute joint turns
by ``theta_J`` (variables ``c_J, s_J`` with ``c_J^2 + s_J^2 = 1``: the cosine and sine of the
relative joint angle), a prismatic joint slides by ``d_J``, a cylindrical joint does both, a
universal joint turns by ``theta_J`` and then by ``theta2_J`` (``c2_J, s2_J``) about the
perpendicular axis x.  The loop closes when ``T_1 T_2 ... T_n = I``.

Closure equations: when two consecutive revolute joints ``k, k+1`` are joined by a link with a
twist (sin != 0), the loop is cut there: with the rest of the loop split into two halves ``F``
and ``H`` (the frames whose z-axes are the axes of joints ``k`` and ``k+1``), the link closes the
loop iff the two axes, lines ``(P, u)`` and ``(Q, v)``, keep the link's twist, offset and length:

    u.v = cos(twist),   u.(Q - P) = d,   v.(Q - P) = d cos(twist),   u.((Q - P) x v) = -a sin(twist)

(four equations, each of low degree in the two halves), and ``theta_k``, ``theta_{k+1}`` are
polynomials in the other joint variables — they are left out of the ring (the configuration
space is the same curve, isomorphically projected).  Otherwise the closure ``T_1...T_m =
(T_{m+1}...T_n)^{-1}`` gives twelve equations (zero and repeated ones dropped).  Polynomials are
reduced modulo the circles and made primitive.
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Optional, Sequence

from mech.kernel import Poly, PolyRing, normal_form
from mech.stdlib.joints import Cylindrical, Described, Length, LoopJoint, MechanismError, Prismatic, Revolute, Universal


Matrix = list[list[Any]]


# ---------------------------------------------------------------- rigid transformations
class Frame:
    """A rigid transformation ``x -> rot x + trans`` with entries in a ring (polynomials or floats)."""

    def __init__(self, rot: Matrix, trans: list[Any]) -> None:
        self.rot, self.trans = rot, trans

    @staticmethod
    def identity() -> "Frame":
        return Frame([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 0])

    def __mul__(self, other: "Frame") -> "Frame":
        r, t = self.rot, self.trans
        rot = [[_dot(r[i], [other.rot[k][j] for k in range(3)]) for j in range(3)] for i in range(3)]
        trans = [_dot(r[i], other.trans) + t[i] for i in range(3)]
        return Frame(rot, trans)

    def inverse(self) -> "Frame":
        rt = [[self.rot[j][i] for j in range(3)] for i in range(3)]
        return Frame(rt, [-_dot(rt[i], self.trans) for i in range(3)])

    def column(self, j: int) -> list[Any]:
        return [self.rot[i][j] for i in range(3)]


def _dot(a: Sequence[Any], b: Sequence[Any]) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a: Sequence[Any], b: Sequence[Any]) -> list[Any]:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def rot_z(c: Any, s: Any) -> Frame:
    return Frame([[c, -s, 0], [s, c, 0], [0, 0, 1]], [0, 0, 0])


def link_frame(d: Any, a: Any, twist: tuple[Any, Any]) -> Frame:
    """``Tz(d) Tx(a) Rx(twist)``: from a joint's axis to the next one's."""
    ca, sa = twist
    return Frame([[1, 0, 0], [0, ca, -sa], [0, sa, ca]], [a, 0, d])


def joint_frame(j: LoopJoint, v: dict[str, Any], param: Any) -> Frame:
    """``T_J`` with the joint variables' values ``v`` (keys theta, d, theta2 as (c, s) or a value)
    and ``param`` turning a parameter (number or name) into a ring element."""
    c, s = v["theta"] if "theta" in v else (param(j.theta[0]), param(j.theta[1]))
    d = v["d"] if "d" in v else param(j.d)
    turn = rot_z(c, s)
    if isinstance(j, Universal):
        c2, s2 = v["theta2"]
        turn = turn * Frame([[1, 0, 0], [0, 0, -1], [0, 1, 0]], [0, 0, 0]) * rot_z(c2, s2)
    return turn * link_frame(d, param(j.a), (param(j.twist[0]), param(j.twist[1])))


# ---------------------------------------------------------------- variables
def joint_variable_names(j: LoopJoint) -> dict[str, tuple[str, ...]]:
    """The ring variables of a joint, by what they measure."""
    out: dict[str, tuple[str, ...]] = {}
    for var in j.joint_variables:
        if var == "theta":
            out[var] = (f"c_{j.name}", f"s_{j.name}")
        elif var == "theta2":
            out[var] = (f"c2_{j.name}", f"s2_{j.name}")
        else:
            out[var] = (f"d_{j.name}",)
    return out


def cut_link(m: Described) -> Optional[int]:
    """The index k (0-based) of the link cut: joints k and k+1 (cyclically) plain revolute joints
    and the link's twist not 0 or 180 degrees; the one nearest the middle of the loop."""
    joints = m.joints
    n = len(joints)
    if n < 3:
        return None
    ok = [k for k in range(n) if type(joints[k]) is Revolute and type(joints[(k + 1) % n]) is Revolute
          and joints[k].twist[1] != 0]
    return min(ok, key=lambda k: (abs(2 * k + 1 - n), k)) if ok else None


def variables(m: Described) -> list[str]:
    k = cut_link(m)
    n = len(m.joints)
    cut = set() if k is None else {k, (k + 1) % n}
    return [name for i, j in enumerate(m.joints) if i not in cut for names in joint_variable_names(j).values()
            for name in names]


# ---------------------------------------------------------------- equations
def constraints(m: Described, values: dict[str, Length]) -> tuple[PolyRing, list[Poly]]:
    joints = m.joints
    n = len(joints)
    if n < 2:
        raise MechanismError(f"{m.name}: a loop needs at least two joints")
    R = m.ring(values)
    gens = dict(zip(R.names, R.gens()))

    def param(v: Length) -> Poly:
        if isinstance(v, str):
            v = values.get(v, v)
        return gens[v] if isinstance(v, str) else R.const(Fraction(v))

    def frame(i: int) -> Frame:
        j = joints[i]
        v = {var: tuple(gens[x] for x in names) if len(names) == 2 else gens[names[0]]
             for var, names in joint_variable_names(j).items()}
        return joint_frame(j, v, param)

    circles = [gens[f"c{p}_{j.name}"] ** 2 + gens[f"s{p}_{j.name}"] ** 2 - 1 for j in joints
               for p in ("", "2") if f"c{p}_{j.name}" in gens]
    k = cut_link(m)
    if k is not None:
        rest = [(k + 2 + i) % n for i in range(n - 2)]
        half = len(rest) // 2
        left = _product([frame(i) for i in rest[half:]])       # F: its z-axis is joint k's axis
        right = _product([frame(i) for i in rest[:half]]).inverse()
        nxt = joints[(k + 1) % n]
        right = right * link_frame(param(nxt.d), param(nxt.a), (param(nxt.twist[0]), param(nxt.twist[1]))).inverse()
        jk = joints[k]
        ca, sa = param(jk.twist[0]), param(jk.twist[1])
        P, u, Q, v = left.trans, left.column(2), right.trans, right.column(2)
        D = [q - p for p, q in zip(P, Q)]
        closure = [_dot(u, v) - ca, _dot(u, D) - param(jk.d), _dot(v, D) - param(jk.d) * ca,
                   _dot(u, _cross(D, v)) + param(jk.a) * sa]
    else:
        m_ = (n + 1) // 2
        left = _product([frame(i) for i in range(m_)])
        right = _product([frame(i) for i in range(m_, n)]).inverse()
        closure = [left.rot[i][j] - right.rot[i][j] for i in range(3) for j in range(3)]
        closure += [left.trans[i] - right.trans[i] for i in range(3)]
    return R, _distinct([_reduce(g, circles, R) for g in closure]) + circles


def _product(frames: Sequence[Frame]) -> Frame:
    out = Frame.identity()
    for f in frames:
        out = out * f
    return out


def _reduce(g: Any, circles: list[Poly], R: PolyRing) -> Poly:
    """``g`` modulo the circles (lower degrees), primitive with a positive leading coefficient."""
    from mech.stdlib.standard import normalize
    g = g if isinstance(g, Poly) else R.const(Fraction(g))
    return normalize(normal_form(g, circles)) if circles and not g.is_zero() else normalize(g)


def _distinct(polys: list[Poly]) -> list[Poly]:
    out: list[Poly] = []
    for g in polys:
        if g.is_zero() or g in out or (-g) in out:
            continue
        if g.is_constant():
            raise MechanismError("the loop cannot close: a closure equation is a non-zero constant "
                                 "(the offsets or lengths along parallel axes do not add up)")
        out.append(g)
    return out


# ---------------------------------------------------------------- counts and values
def gruebler_kutzbach(m: Described) -> tuple[int, int]:
    """``(count, lambda)``: ``lambda (n - 1) - sum (lambda - f_j)`` for one loop of n joints
    (= ``sum f_j - lambda``), with lambda = 3 for a spherical loop (revolute joints whose axes meet
    in one point: every a and d zero) or a planar one (revolute joints with parallel axes: every
    twist 0 or 180 degrees), 6 otherwise."""
    joints = m.joints
    revolute = all(type(j) is Revolute for j in joints)
    spherical = revolute and all(j.a == 0 and j.d == 0 for j in joints)
    planar = revolute and all(j.twist[1] == 0 for j in joints)
    lam = 3 if spherical or planar else 6
    return sum(j.freedom for j in joints) - lam, lam


def joint_values(m: Described, config: dict[str, float]) -> list[dict[str, Any]]:
    """Every joint's values (``theta`` and ``theta2`` as (cos, sin), ``d``) at a configuration
    given by the ring variables' values (floats; parameters included); the cut joints' angles
    computed from the others."""
    joints = m.joints
    n = len(joints)

    def param(v: Length) -> float:
        return config[v] if isinstance(v, str) else float(v)
    vals: list[dict[str, Any]] = []
    for j in joints:
        v: dict[str, Any] = {}
        for var, names in joint_variable_names(j).items():
            if all(x in config for x in names):
                v[var] = tuple(config[x] for x in names) if len(names) == 2 else config[names[0]]
        vals.append(v)
    k = cut_link(m)
    if k is None:
        return vals
    rest = [(k + 2 + i) % n for i in range(n - 2)]
    half = len(rest) // 2
    left = _product([joint_frame(joints[i], vals[i], param) for i in rest[half:]])
    right = _product([joint_frame(joints[i], vals[i], param) for i in rest[:half]]).inverse()
    nxt, jk = joints[(k + 1) % n], joints[k]
    right = right * link_frame(param(nxt.d), param(nxt.a), (float(nxt.twist[0]), float(nxt.twist[1]))).inverse()
    rel = left.inverse() * right  # = Rz(theta_k) K_k Rz(theta_k+1)
    ca, sa = float(jk.twist[0]), float(jk.twist[1])
    r = rel.column(2)
    ck, sk = -r[1] / sa, r[0] / sa
    rest_rot = (link_frame(0.0, 0.0, (ca, sa)).inverse() * rot_z(ck, -sk) * rel).rot
    vals[k]["theta"] = (ck, sk)
    vals[(k + 1) % n]["theta"] = (rest_rot[0][0], rest_rot[1][0])
    return vals


def frames(m: Described, config: dict[str, float]) -> list[Frame]:
    """The frames ``F_0 = I, F_1 = T_1, ..., F_n`` (floats) at a configuration: the z-axis of
    ``F_{i-1}`` is joint i's axis."""
    vals = joint_values(m, config)

    def param(v: Length) -> float:
        return config[v] if isinstance(v, str) else float(v)
    out = [Frame.identity()]
    for j, v in zip(m.joints, vals):
        out.append(out[-1] * joint_frame(j, v, param))
    return out


def degrees(cs: tuple[float, float]) -> float:
    return math.degrees(math.atan2(cs[1], cs[0]))


__all__ = ["Cylindrical", "Prismatic", "Revolute", "Universal", "constraints", "variables",
           "gruebler_kutzbach", "joint_values", "frames", "cut_link"]
