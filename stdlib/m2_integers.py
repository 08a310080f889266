"""Polynomial rings over ZZ in the Macaulay2 dialect (``ZZ[x,y]``): which commands are exact
there.  Elements are integral polynomials under QQ's arithmetic (a fractional coefficient is
refused: :mod:`mech.dsl.m2_ops`); the commands marked here never divide nor compute a Gröbner
basis (the list library, printing, matrices, derivatives, determinants, resultants,
substitutions and ring maps) or compute with strong Gröbner bases (:mod:`mech.kernel.zz_groebner`:
``trim``, ``mingens``, ``eliminate``, ``intersect``, ``quotient``, ``saturate``, ``==`` and ``isSubset`` on ideals); the
others refuse elements of rings over ZZ."""
from __future__ import annotations

from . import m2, m2_ideals, m2_lists, m2_local, m2_matrices, m2_modules, m2_monoids

_EXACT = (m2.ideal, m2.matrix, m2.gens, m2.numgens, m2.entries, m2_matrices.submatrix, m2_matrices.det, m2_matrices.minors, m2_matrices.jacobian,
          m2_matrices.diff, m2_matrices.sub, m2.use, m2.degree, m2_ideals.generators, m2_ideals.numgens_ring, m2_ideals.vars_,
          m2_ideals.generic_matrix, m2_ideals.numcols, m2_ideals.numrows, m2_ideals.support, m2_ideals.terms,
          m2_ideals.terms_over, m2_ideals.lead_term, m2_ideals.lead_monomial, m2_ideals.lead_coefficient,
          m2_ideals.is_homogeneous, m2_ideals.degrees, m2_ideals.homogenize, m2_ideals.substitute,
          m2_ideals.ring, m2_ideals.map_, m2_ideals.matrix_of_map, m2_ideals.source, m2_ideals.target,
          m2_ideals.coefficient_ring, m2_ideals.base_name, m2_ideals.resultant, m2_ideals.discriminant,
          m2_ideals.sylvester_matrix, m2_matrices.factor, m2_matrices.value, m2_modules.map_modules, m2_modules.identity, m2_modules.source,
          m2_modules.target, m2_modules.degrees, m2_modules.rank, m2_modules.numgens, m2_modules.is_homogeneous,
          m2_modules.transpose, m2_local.numerator, m2_local.denominator,
          m2_ideals.monomial_ideal, m2_ideals.degree_in, m2_modules.transpose_table, m2.eliminate, m2.eliminate_ideal_first, m2.quotient_cmd, m2.saturate,
          m2.intersect, m2.matrix_of_element, m2_matrices.submatrix_without, m2_local.promote, m2_monoids.monoid,
          m2_matrices.exterior_power, m2_ideals.trim, m2_ideals.mingens, m2_matrices.permanents, m2_modules.dual, m2_modules.map_identity)
for _f in _EXACT:
    _f.zz_ok = True
for _name in dir(m2_lists):  # the list library: no arithmetic of its own (isSubset checks its ideals)
    _f = getattr(m2_lists, _name)
    if callable(_f) and getattr(_f, "__module__", "") == m2_lists.__name__ and hasattr(_f, "quotient_ok"):
        _f.zz_ok = True
