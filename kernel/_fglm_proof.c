/* The exact check of a lifted FGLM conversion (kernel/fglm.py ``_proved``), part of the module
 * mech.kernel._fglm: whether polynomials with integer coefficients top-reduce to 0 by a basis.
 *
 * fglm_reduces(n, W, basis_offsets, basis_exps, basis_nums, basis_dens, offsets, exps, nums, dens)
 * with W the ordering's nonnegative n x n weight matrix (int64, row by row), each polynomial's
 * terms from offsets[i] to offsets[i+1] (exponents n int32 a term, rational coefficients as
 * int64 numerators and positive denominators), the leading term of each basis element anywhere
 * among its terms; every polynomial is first scaled to its primitive integer multiple.  Returns 1
 * if every polynomial top-reduces to 0, 0 if one does not, -1 if the check left 64 bits (a
 * coefficient or a packed field; the caller
 * then checks in Python with unbounded integers).
 *
 * Fraction-free, as kernel/hilbert_compiled.py ``reduce_to_zero``: the step a p - c x^s g with
 * a c = lc(g) lc(p) / gcd cancels the top term without a division, the content is divided out
 * after a step that scaled p.  A term is (key, exps, coef): key packs W e field by field (the
 * ordering is the integer order of keys), exps packs e (divisibility by guard bits); both add
 * under multiplication, and every field keeps a guard bit that flags an overflow. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include "_intmath.h"
#include <stdint.h>
#include <stdlib.h>

typedef struct {
    uint64_t key, exps;
    int64_t coef;
} Term;

typedef struct {
    Term *t;
    Py_ssize_t len, cap;
} Poly;

static int reserve(Poly *p, Py_ssize_t cap)
{
    if (cap <= p->cap)
        return 1;
    Term *t = realloc(p->t, (size_t)cap * sizeof(Term));
    if (!t)
        return 0;
    p->t = t;
    p->cap = cap;
    return 1;
}

static int by_key_desc(const void *a, const void *b)
{
    const uint64_t x = ((const Term *)a)->key, y = ((const Term *)b)->key;
    return (x < y) - (x > y);
}

/* The packing: field widths for W e (each bounded by max W[r] * top) and for e (bounded by top),
 * a guard bit each; 0 if it does not fit 64 bits. */
typedef struct {
    Py_ssize_t n;
    int kshift[64], eshift[64];
    uint64_t kguard, eguard;
} Packing;

static int bits_of(uint64_t v)
{
    int b = 0;
    while (v) {
        b++;
        v >>= 1;
    }
    return b;
}

static int packing_init(Packing *P, Py_ssize_t n, const int64_t *W, int64_t top)
{
    int pos = 0;
    P->n = n;
    P->kguard = P->eguard = 0;
    if (n > 32)
        return 0;
    for (Py_ssize_t r = n - 1; r >= 0; r--) { /* the first row in the highest field */
        int64_t m = 0;
        for (Py_ssize_t j = 0; j < n; j++) {
            if (W[r * n + j] < 0)
                return 0;
            if (W[r * n + j] > m)
                m = W[r * n + j];
        }
        if (m > INT64_MAX / top)
            return 0;
        const int w = bits_of((uint64_t)(m * top)) + 1;
        P->kshift[r] = pos;
        pos += w;
        if (pos > 64)
            return 0;
        P->kguard |= 1ULL << (pos - 1);
    }
    const int ew = bits_of((uint64_t)top) + 1;
    if (ew * n > 64)
        return 0;
    for (Py_ssize_t j = 0; j < n; j++) {
        P->eshift[j] = (int)(ew * j);
        P->eguard |= 1ULL << (ew * j + ew - 1);
    }
    return 1;
}

static int pack(const Packing *P, const int64_t *W, const int32_t *e, Term *t)
{
    const Py_ssize_t n = P->n;
    t->key = t->exps = 0;
    for (Py_ssize_t j = 0; j < n; j++) {
        if (e[j] < 0)
            return 0;
        t->exps += (uint64_t)e[j] << P->eshift[j];
    }
    for (Py_ssize_t r = 0; r < n; r++) {
        uint64_t v = 0;
        for (Py_ssize_t j = 0; j < n; j++)
            v += (uint64_t)W[r * n + j] * (uint64_t)e[j];
        t->key += v << P->kshift[r];
    }
    return !(t->key & P->kguard) && !(t->exps & P->eguard);
}

/* Reads polynomials (offsets, exponents, numerators, denominators) into sorted term arrays, each
 * scaled to its primitive integer multiple (-1 if that leaves 64 bits). */
static int read_polys(const Packing *P, const int64_t *W, Py_buffer *off, Py_buffer *ex, Py_buffer *nu,
                      Py_buffer *de, Poly **out, Py_ssize_t *count)
{
    const int64_t *O = off->buf;
    const int32_t *E = ex->buf;
    const int64_t *C = nu->buf, *Q = de->buf;
    const Py_ssize_t m = off->len / 8 - 1, T = nu->len / 8;
    if (m < 0 || ex->len / 4 < T * P->n || de->len / 8 < T)
        return -2;
    Poly *ps = calloc((size_t)(m + 1), sizeof(Poly));
    if (!ps)
        return -3;
    *out = ps;
    *count = m;
    for (Py_ssize_t i = 0; i < m; i++) {
        const Py_ssize_t a = O[i], b = O[i + 1];
        if (a < 0 || b < a || b > T)
            return -2;
        if (!reserve(ps + i, b - a + 1))
            return -3;
        int64_t den = 1, cont = 0;
        for (Py_ssize_t k = a; k < b; k++) {
            if (Q[k] <= 0)
                return -2;
            const int64_t g = gcd_i64(den, Q[k]);
            if (__builtin_mul_overflow(den / g, Q[k], &den))
                return -1;
        }
        for (Py_ssize_t k = a; k < b; k++) {
            Term *t = ps[i].t + (k - a);
            if (!pack(P, W, E + k * P->n, t))
                return -1;
            if (C[k] == INT64_MIN || __builtin_mul_overflow(C[k], den / Q[k], &t->coef) || t->coef == INT64_MIN)
                return -1;
            cont = gcd_i64(cont, t->coef);
        }
        ps[i].len = b - a;
        if (cont > 1)
            for (Py_ssize_t k = 0; k < ps[i].len; k++)
                ps[i].t[k].coef /= cont;
        qsort(ps[i].t, (size_t)ps[i].len, sizeof(Term), by_key_desc);
    }
    return 0;
}

/* p <- a * p[1:] - c * x^s * g[1:], equal keys merged; -1 on an overflow, -3 out of memory. */
static int step(const Packing *P, Poly *p, const Poly *g, uint64_t skey, uint64_t sexps, int64_t a, int64_t c,
                Poly *tmp)
{
    if (!reserve(tmp, p->len + g->len))
        return -3;
    Py_ssize_t i = 1, j = 1, k = 0;
    while (i < p->len || j < g->len) {
        Term t;
        int64_t v;
        if (j < g->len) {
            t.key = g->t[j].key + skey;
            t.exps = g->t[j].exps + sexps;
            if ((t.key & P->kguard) || (t.exps & P->eguard))
                return -1;
        }
        if (j >= g->len || (i < p->len && p->t[i].key > t.key)) {
            if (__builtin_mul_overflow(p->t[i].coef, a, &v))
                return -1;
            t = p->t[i++];
        } else if (i < p->len && p->t[i].key == t.key) {
            int64_t u, w;
            if (__builtin_mul_overflow(p->t[i].coef, a, &u) || __builtin_mul_overflow(g->t[j].coef, c, &w)
                || __builtin_sub_overflow(u, w, &v))
                return -1;
            i++, j++;
            if (!v)
                continue;
        } else {
            if (__builtin_mul_overflow(g->t[j].coef, c, &v) || v == INT64_MIN)
                return -1;
            v = -v;
            j++;
        }
        if (v == INT64_MIN)
            return -1;
        t.coef = v;
        tmp->t[k++] = t;
    }
    tmp->len = k;
    Poly swap = *p;
    *p = *tmp;
    *tmp = swap;
    if (a != 1 && p->len > 1) {
        int64_t cont = 0;
        for (Py_ssize_t r = 0; r < p->len && cont != 1; r++)
            cont = gcd_i64(cont, p->t[r].coef);
        if (cont > 1)
            for (Py_ssize_t r = 0; r < p->len; r++)
                p->t[r].coef /= cont;
    }
    return 0;
}

static int reduces(const Packing *P, const Poly *basis, Py_ssize_t nb, Poly *p, Poly *tmp)
{
    while (p->len) {
        const Term top = p->t[0];
        const Poly *g = NULL;
        for (Py_ssize_t k = 0; k < nb && !g; k++) {
            const uint64_t lm = basis[k].t[0].exps;
            if ((((top.exps | P->eguard) - lm) & P->eguard) == P->eguard)
                g = basis + k;
        }
        if (!g)
            return 0;
        int64_t a = g->t[0].coef, c = top.coef;
        const int64_t d = gcd_i64(a, c);
        a /= d, c /= d;
        if (a < 0)
            a = -a, c = -c;
        const int r = step(P, p, g, top.key - g->t[0].key, top.exps - g->t[0].exps, a, c, tmp);
        if (r < 0)
            return r;
    }
    return 1;
}

PyObject *fglm_reduces(PyObject *self, PyObject *args)
{
    Py_ssize_t n;
    Py_buffer Wb, bo, be, bc, bd, po, pe, pc, pd;
    if (!PyArg_ParseTuple(args, "ny*y*y*y*y*y*y*y*y*", &n, &Wb, &bo, &be, &bc, &bd, &po, &pe, &pc, &pd))
        return NULL;
    const int64_t *W = Wb.buf;
    Poly *basis = NULL, *polys = NULL, tmp = {0};
    Py_ssize_t nb = 0, np = 0;
    int result = -2;
    Packing P;
    if (Wb.len / 8 < n * n || n <= 0)
        goto done;
    /* the degree bound: reductions keep terms below the top one; the guards catch the rest */
    int64_t top = 1;
    const int32_t *E[2] = {be.buf, pe.buf};
    const Py_ssize_t T[2] = {bc.len / 8, pc.len / 8};
    for (int s = 0; s < 2; s++) {
        if (E[s] && (Py_ssize_t)((s ? pe.len : be.len) / 4) < T[s] * n)
            goto done;
        for (Py_ssize_t k = 0; k < T[s]; k++) {
            int64_t d = 0;
            for (Py_ssize_t j = 0; j < n; j++)
                d += E[s][k * n + j];
            if (d > top)
                top = d;
        }
    }
    result = packing_init(&P, n, W, 2 * top + 2) ? 0 : -1;
    if (result < 0)
        goto done;
    if ((result = read_polys(&P, W, &bo, &be, &bc, &bd, &basis, &nb))
        || (result = read_polys(&P, W, &po, &pe, &pc, &pd, &polys, &np)))
        goto done;
    for (Py_ssize_t k = 0; k < nb; k++)
        if (!basis[k].len) {
            result = -2;
            goto done;
        }
    result = 1;
    for (Py_ssize_t i = 0; i < np && result == 1; i++)
        result = reduces(&P, basis, nb, polys + i, &tmp);
done:
    if (basis)
        for (Py_ssize_t k = 0; k <= nb; k++)
            free(basis[k].t);
    if (polys)
        for (Py_ssize_t k = 0; k <= np; k++)
            free(polys[k].t);
    free(basis);
    free(polys);
    free(tmp.t);
    PyBuffer_Release(&Wb);
    PyBuffer_Release(&bo);
    PyBuffer_Release(&be);
    PyBuffer_Release(&bc);
    PyBuffer_Release(&bd);
    PyBuffer_Release(&po);
    PyBuffer_Release(&pe);
    PyBuffer_Release(&pc);
    PyBuffer_Release(&pd);
    if (result == -2) {
        PyErr_SetString(PyExc_ValueError, "fglm_reduces: inconsistent arrays");
        return NULL;
    }
    if (result == -3)
        return PyErr_NoMemory();
    return PyLong_FromLong(result);
}
