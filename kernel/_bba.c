/* The Hilbert-driven Buchberger algorithm modulo p < 2^31 and the reduction of its basis
 * (kernel/hilbert_compiled.py drives it), the optional extension mech.kernel._bba.
 *
 * Monomials are the packed integers of kernel/monomials.py (``Packing``), split into `nw`
 * little-endian 64-bit words: comparing them word by word from the top compares the monomials
 * in the ordering, a product is a sum, ``a | b`` is ``((b | G) - a) & G == G`` with the guard
 * bits G, and a guard bit set in a product means the packing is too narrow (Overflow).
 * A layout (capsule) holds the words, the guard bits, each variable's exponent field and packed
 * unit (for lcms), and the degree field.
 *
 * A state (capsule) holds the generators, the basis (monic, terms in decreasing order) and the
 * pairs (degree of the lcm, lcm, i, j; j = -1: generator i waiting) under the Gebauer-Moeller
 * criteria.  step(st, d, need) takes the pairs of degree d in increasing (lcm, i, j) order and
 * top-reduces their S-polynomials until `need` new leading monomials are found; the caller
 * (which knows the Hilbert series) decides the degree and the need.  reduced(st, target) gives
 * the reduced basis of the active elements, their monomials first mapped to the layout
 * `target` (dehomogenization: the exponents of its variables kept, the others dropped). */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define MAXW 8

typedef struct {
    int nw, n, dshift, ebits;
    uint64_t guard[MAXW];
    uint64_t *units; /* n * nw */
    int *eshift;     /* n */
} Layout;

typedef struct {
    Py_ssize_t len;
    uint64_t *m; /* len * nw, decreasing */
    uint32_t *c;
} Poly;

typedef struct {
    int deg, i, j;
    uint64_t lcm[MAXW];
} Pair;

typedef struct {
    Layout *L;
    PyObject *layout; /* owns L */
    uint64_t p;
    Poly *gens, *basis;
    char *active;
    Py_ssize_t ngens, nb, capb;
    Pair *pairs;
    Py_ssize_t np, capp;
    Poly scratch, work;
    Py_ssize_t capscratch, capwork;
} State;

/* -- monomials ------------------------------------------------------------------------------ */
static inline int mcmp(const uint64_t *a, const uint64_t *b, int nw)
{
    for (int k = nw - 1; k >= 0; k--)
        if (a[k] != b[k])
            return a[k] > b[k] ? 1 : -1;
    return 0;
}

static inline void madd(uint64_t *out, const uint64_t *a, const uint64_t *b, int nw)
{
    unsigned __int128 carry = 0;
    for (int k = 0; k < nw; k++) {
        carry += (unsigned __int128)a[k] + b[k];
        out[k] = (uint64_t)carry;
        carry >>= 64;
    }
}

static inline void msub(uint64_t *out, const uint64_t *a, const uint64_t *b, int nw)
{
    uint64_t borrow = 0;
    for (int k = 0; k < nw; k++) {
        uint64_t x = a[k], y = b[k];
        uint64_t d = x - y - borrow;
        borrow = (x < y) || (x - y < borrow);
        out[k] = d;
    }
}

static inline int mdivides(const Layout *L, const uint64_t *a, const uint64_t *b)
{
    uint64_t t[MAXW], bg[MAXW];
    for (int k = 0; k < L->nw; k++)
        bg[k] = b[k] | L->guard[k];
    msub(t, bg, a, L->nw);
    for (int k = 0; k < L->nw; k++)
        if ((t[k] & L->guard[k]) != L->guard[k])
            return 0;
    return 1;
}

static inline int mguarded(const Layout *L, const uint64_t *a)
{
    for (int k = 0; k < L->nw; k++)
        if (a[k] & L->guard[k])
            return 1;
    return 0;
}

static inline uint64_t field(const uint64_t *a, int shift, int width)
{
    int w = shift >> 6, off = shift & 63;
    uint64_t v = a[w] >> off;
    if (off + width > 64)
        v |= a[w + 1] << (64 - off);
    return v & ((width >= 64) ? ~(uint64_t)0 : (((uint64_t)1 << width) - 1));
}

static inline int mdegree(const Layout *L, const uint64_t *a)
{
    return (int)field(a, L->dshift, L->ebits);
}

/* out += x * unit (x small) */
static inline void maddmul(uint64_t *out, const uint64_t *unit, uint64_t x, int nw)
{
    unsigned __int128 carry = 0;
    for (int k = 0; k < nw; k++) {
        carry += (unsigned __int128)out[k] + (unsigned __int128)unit[k] * x;
        out[k] = (uint64_t)carry;
        carry >>= 64;
    }
}

static void mlcm(const Layout *L, uint64_t *out, const uint64_t *a, const uint64_t *b)
{
    memcpy(out, a, sizeof(uint64_t) * L->nw);
    for (int j = 0; j < L->n; j++) {
        uint64_t ea = field(a, L->eshift[j], L->ebits), eb = field(b, L->eshift[j], L->ebits);
        if (eb > ea)
            maddmul(out, L->units + (size_t)j * L->nw, eb - ea, L->nw);
    }
}

/* -- layouts ------------------------------------------------------------------------------- */
static void layout_free(PyObject *cap)
{
    Layout *L = PyCapsule_GetPointer(cap, "bba.layout");
    if (L) {
        free(L->units);
        free(L->eshift);
        free(L);
    }
}

/* layout(nw, guard: bytes, units: bytes (n * nw words), eshifts: tuple, dshift, ebits) */
static PyObject *bba_layout(PyObject *self, PyObject *args)
{
    int nw, dshift, ebits;
    Py_buffer guard, units;
    PyObject *eshifts;
    if (!PyArg_ParseTuple(args, "iy*y*O!ii", &nw, &guard, &units, &PyTuple_Type, &eshifts, &dshift, &ebits))
        return NULL;
    PyObject *out = NULL;
    Py_ssize_t n = PyTuple_GET_SIZE(eshifts);
    if (nw < 1 || nw > MAXW || guard.len != 8 * nw || units.len != 8 * nw * n) {
        PyErr_SetString(PyExc_ValueError, "bba.layout: bad sizes");
        goto done;
    }
    Layout *L = calloc(1, sizeof(Layout));
    if (!L) {
        PyErr_NoMemory();
        goto done;
    }
    L->nw = nw;
    L->n = (int)n;
    L->dshift = dshift;
    L->ebits = ebits;
    memcpy(L->guard, guard.buf, guard.len);
    L->units = malloc(units.len ? units.len : 8);
    L->eshift = malloc(sizeof(int) * (n ? n : 1));
    if (!L->units || !L->eshift) {
        free(L->units);
        free(L->eshift);
        free(L);
        PyErr_NoMemory();
        goto done;
    }
    memcpy(L->units, units.buf, units.len);
    for (Py_ssize_t j = 0; j < n; j++)
        L->eshift[j] = (int)PyLong_AsLong(PyTuple_GET_ITEM(eshifts, j));
    out = PyCapsule_New(L, "bba.layout", layout_free);
    if (!out) {
        free(L->units);
        free(L->eshift);
        free(L);
    }
done:
    PyBuffer_Release(&guard);
    PyBuffer_Release(&units);
    return out;
}

/* -- polynomials ---------------------------------------------------------------------------- */
static int poly_reserve(Poly *f, Py_ssize_t *cap, Py_ssize_t len, int nw)
{
    if (len <= *cap)
        return 0;
    Py_ssize_t c = *cap ? *cap : 64;
    while (c < len)
        c *= 2;
    uint64_t *m = realloc(f->m, sizeof(uint64_t) * nw * c);
    if (!m)
        return -1;
    f->m = m;
    uint32_t *cc = realloc(f->c, sizeof(uint32_t) * c);
    if (!cc)
        return -1;
    f->c = cc;
    *cap = c;
    return 0;
}

static int poly_copy(Poly *dst, const uint64_t *m, const uint32_t *c, Py_ssize_t len, int nw)
{
    dst->len = len;
    dst->m = malloc(sizeof(uint64_t) * nw * (len ? len : 1));
    dst->c = malloc(sizeof(uint32_t) * (len ? len : 1));
    if (!dst->m || !dst->c)
        return -1;
    memcpy(dst->m, m, sizeof(uint64_t) * nw * len);
    memcpy(dst->c, c, sizeof(uint32_t) * len);
    return 0;
}

static uint64_t inv_mod(uint64_t a, uint64_t p)
{
    int64_t t = 0, nt = 1, r = (int64_t)p, nr = (int64_t)(a % p);
    while (nr) {
        int64_t q = r / nr, tmp;
        tmp = t - q * nt;
        t = nt;
        nt = tmp;
        tmp = r - q * nr;
        r = nr;
        nr = tmp;
    }
    return (uint64_t)(t < 0 ? t + (int64_t)p : t);
}

static void poly_monic(Poly *f, uint64_t p)
{
    if (!f->len || f->c[0] == 1)
        return;
    uint64_t inv = inv_mod(f->c[0], p);
    for (Py_ssize_t k = 0; k < f->len; k++)
        f->c[k] = (uint32_t)(f->c[k] * inv % p);
}

/* out = a[ia..] - ca * (ta * b[ib..]) as a merge (decreasing monomials); ta may be NULL (1).
 * -1 and the Overflow flag when a product leaves the packing. */
static int merge_sub(State *S, Poly *out, Py_ssize_t *capout, const uint64_t *am, const uint32_t *ac,
                     Py_ssize_t alen, const uint64_t *ta, uint64_t ca, const Poly *b, Py_ssize_t ib, int *overflow)
{
    const Layout *L = S->L;
    const int nw = L->nw;
    const uint64_t p = S->p, neg = (p - ca % p) % p;
    if (poly_reserve(out, capout, alen + (b->len - ib), nw) < 0)
        return -2;
    Py_ssize_t i = 0, k = ib, o = 0;
    uint64_t tm[MAXW];
    int have = 0;
    while (i < alen || k < b->len) {
        if (k < b->len && !have) {
            if (ta) {
                madd(tm, b->m + (size_t)k * nw, ta, nw);
                if (mguarded(L, tm)) {
                    *overflow = 1;
                    return -1;
                }
            } else
                memcpy(tm, b->m + (size_t)k * nw, 8 * nw);
            have = 1;
        }
        int c = (i >= alen) ? -1 : (!have ? 1 : mcmp(am + (size_t)i * nw, tm, nw));
        if (c > 0) {
            memcpy(out->m + (size_t)o * nw, am + (size_t)i * nw, 8 * nw);
            out->c[o++] = ac[i++];
        } else if (c < 0) {
            uint64_t v = neg * b->c[k] % p;
            if (v) {
                memcpy(out->m + (size_t)o * nw, tm, 8 * nw);
                out->c[o++] = (uint32_t)v;
            }
            k++;
            have = 0;
        } else {
            uint64_t v = (ac[i] + neg * b->c[k]) % p;
            if (v) {
                memcpy(out->m + (size_t)o * nw, tm, 8 * nw);
                out->c[o++] = (uint32_t)v;
            }
            i++;
            k++;
            have = 0;
        }
    }
    out->len = o;
    return 0;
}

static void swap_polys(Poly *a, Py_ssize_t *capa, Poly *b, Py_ssize_t *capb)
{
    Poly t = *a;
    *a = *b;
    *b = t;
    Py_ssize_t c = *capa;
    *capa = *capb;
    *capb = c;
}

/* the first reducer (in order) whose leading monomial divides m, or -1 */
static Py_ssize_t find_reducer(const Layout *L, const Poly *red, Py_ssize_t nred, const uint64_t *m)
{
    for (Py_ssize_t r = 0; r < nred; r++)
        if (mdivides(L, red[r].m, m))
            return r;
    return -1;
}

/* S->work := its normal form by the reducers: only the top (full = 0) or every term (full = 1,
 * the irreducible terms collected in S->scratch first, then copied back). */
static int reduce_work(State *S, const Poly *red, Py_ssize_t nred, int full, int *overflow)
{
    const Layout *L = S->L;
    const int nw = L->nw;
    Poly done = {0, NULL, NULL}, tmp = {0, NULL, NULL};
    Py_ssize_t capdone = 0, captmp = 0, off = 0;
    int rc = 0;
    uint64_t t[MAXW];
    while (off < S->work.len) {
        const uint64_t *lead = S->work.m + (size_t)off * nw;
        Py_ssize_t r = find_reducer(L, red, nred, lead);
        if (r < 0) {
            if (!full)
                break;
            if (poly_reserve(&done, &capdone, done.len + 1, nw) < 0) {
                rc = -2;
                break;
            }
            memcpy(done.m + (size_t)done.len * nw, lead, 8 * nw);
            done.c[done.len++] = S->work.c[off++];
            continue;
        }
        msub(t, lead, red[r].m, nw);
        uint64_t c = S->work.c[off];
        rc = merge_sub(S, &tmp, &captmp, S->work.m + (size_t)(off + 1) * nw, S->work.c + off + 1,
                       S->work.len - off - 1, t, c, &red[r], 1, overflow);
        if (rc < 0)
            break;
        swap_polys(&S->work, &S->capwork, &tmp, &captmp);
        off = 0;
    }
    if (rc == 0) {
        Py_ssize_t rest = S->work.len - off;
        if (poly_reserve(&done, &capdone, done.len + rest, nw) < 0)
            rc = -2;
        else {
            memcpy(done.m + (size_t)done.len * nw, S->work.m + (size_t)off * nw, 8 * nw * rest);
            memcpy(done.c + done.len, S->work.c + off, 4 * rest);
            done.len += rest;
            swap_polys(&S->work, &S->capwork, &done, &capdone);
        }
    }
    free(done.m);
    free(done.c);
    free(tmp.m);
    free(tmp.c);
    return rc;
}

/* -- states --------------------------------------------------------------------------------- */
static void state_free(PyObject *cap)
{
    State *S = PyCapsule_GetPointer(cap, "bba.state");
    if (!S)
        return;
    for (Py_ssize_t k = 0; k < S->ngens; k++) {
        free(S->gens[k].m);
        free(S->gens[k].c);
    }
    for (Py_ssize_t k = 0; k < S->nb; k++) {
        free(S->basis[k].m);
        free(S->basis[k].c);
    }
    free(S->gens);
    free(S->basis);
    free(S->active);
    free(S->pairs);
    free(S->scratch.m);
    free(S->scratch.c);
    free(S->work.m);
    free(S->work.c);
    Py_XDECREF(S->layout);
    free(S);
}

static State *get_state(PyObject *cap)
{
    return PyCapsule_GetPointer(cap, "bba.state");
}

static int push_pair(State *S, int deg, const uint64_t *lcm, int i, int j)
{
    if (S->np == S->capp) {
        Py_ssize_t c = S->capp ? 2 * S->capp : 64;
        Pair *q = realloc(S->pairs, sizeof(Pair) * c);
        if (!q)
            return -1;
        S->pairs = q;
        S->capp = c;
    }
    Pair *a = &S->pairs[S->np++];
    a->deg = deg;
    a->i = i;
    a->j = j;
    memset(a->lcm, 0, sizeof(a->lcm));
    memcpy(a->lcm, lcm, 8 * S->L->nw);
    return 0;
}

/* state(layout, p, gens: list of (monomials bytes, coefficients bytes)) */
static PyObject *bba_state(PyObject *self, PyObject *args)
{
    PyObject *lay, *gens;
    unsigned long long p;
    if (!PyArg_ParseTuple(args, "OKO!", &lay, &p, &PyList_Type, &gens))
        return NULL;
    Layout *L = PyCapsule_GetPointer(lay, "bba.layout");
    if (!L)
        return NULL;
    if (p < 2 || p >= (1ULL << 31)) {
        PyErr_SetString(PyExc_ValueError, "bba.state: p must be below 2^31");
        return NULL;
    }
    State *S = calloc(1, sizeof(State));
    if (!S)
        return PyErr_NoMemory();
    S->L = L;
    S->layout = lay;
    Py_INCREF(lay);
    S->p = p;
    PyObject *cap = PyCapsule_New(S, "bba.state", state_free);
    if (!cap) {
        Py_DECREF(lay);
        free(S);
        return NULL;
    }
    Py_ssize_t ng = PyList_GET_SIZE(gens);
    S->gens = calloc(ng ? ng : 1, sizeof(Poly));
    if (!S->gens) {
        Py_DECREF(cap);
        return PyErr_NoMemory();
    }
    const int nw = L->nw;
    for (Py_ssize_t k = 0; k < ng; k++) {
        PyObject *item = PyList_GET_ITEM(gens, k);
        Py_buffer mb, cb;
        if (!PyArg_ParseTuple(item, "y*y*", &mb, &cb)) {
            Py_DECREF(cap);
            return NULL;
        }
        Py_ssize_t len = cb.len / 4;
        int bad = mb.len != (Py_ssize_t)8 * nw * len || len == 0;
        int err = bad ? 0 : poly_copy(&S->gens[k], mb.buf, cb.buf, len, nw);
        PyBuffer_Release(&mb);
        PyBuffer_Release(&cb);
        S->ngens = k + 1;
        if (bad || err) {
            Py_DECREF(cap);
            if (bad)
                PyErr_SetString(PyExc_ValueError, "bba.state: bad generator");
            else
                PyErr_NoMemory();
            return NULL;
        }
        if (push_pair(S, mdegree(L, S->gens[k].m), S->gens[k].m, (int)k, -1) < 0) {
            Py_DECREF(cap);
            return PyErr_NoMemory();
        }
    }
    return cap;
}

/* The Gebauer-Moeller update after basis element k = nb - 1 joined (kernel/buchberger.py's
 * pair_update with the lcm's degree as the weight). */
static int pair_update(State *S)
{
    const Layout *L = S->L;
    const int nw = L->nw;
    const Py_ssize_t k = S->nb - 1;
    const uint64_t *h = S->basis[k].m;
    const int hdeg = mdegree(L, h);
    Py_ssize_t nnew = 0;
    uint64_t *lcms = malloc(sizeof(uint64_t) * nw * (k ? k : 1));
    int *who = malloc(sizeof(int) * (k ? k : 1));
    char *state = malloc(k ? k : 1); /* 0 dropped, 1 kept, 2 coprime */
    if (!lcms || !who || !state) {
        free(lcms);
        free(who);
        free(state);
        return -2;
    }
    for (Py_ssize_t i = 0; i < k; i++)
        if (S->active[i]) {
            uint64_t *lc = lcms + (size_t)nnew * nw;
            mlcm(L, lc, S->basis[i].m, h);
            if (mguarded(L, lc)) {
                free(lcms);
                free(who);
                free(state);
                return -1;
            }
            who[nnew++] = (int)i;
        }
    for (Py_ssize_t a = 0; a < nnew; a++) {
        const uint64_t *lc = lcms + (size_t)a * nw;
        state[a] = 0;
        int skip = 0;
        for (Py_ssize_t b = 0; b < a && !skip; b++)
            if (state[b] && mcmp(lcms + (size_t)b * nw, lc, nw) == 0)
                skip = 1;
        for (Py_ssize_t b = 0; b < nnew && !skip; b++) {
            const uint64_t *lb = lcms + (size_t)b * nw;
            if (mcmp(lb, lc, nw) != 0 && mdivides(L, lb, lc))
                skip = 1;
        }
        if (skip)
            continue;
        state[a] = (mdegree(L, lc) == mdegree(L, S->basis[who[a]].m) + hdeg) ? 2 : 1;
    }
    /* criterion B on the old pairs */
    uint64_t t[MAXW];
    Py_ssize_t o = 0;
    for (Py_ssize_t q = 0; q < S->np; q++) {
        Pair *a = &S->pairs[q];
        int drop = 0;
        if (a->j >= 0 && mdivides(L, h, a->lcm)) {
            mlcm(L, t, S->basis[a->i].m, h);
            if (mcmp(t, a->lcm, nw) != 0) {
                mlcm(L, t, S->basis[a->j].m, h);
                drop = mcmp(t, a->lcm, nw) != 0;
            }
        }
        if (!drop)
            S->pairs[o++] = *a;
    }
    S->np = o;
    for (Py_ssize_t i = 0; i < k; i++)
        if (S->active[i] && mdivides(L, h, S->basis[i].m))
            S->active[i] = 0;
    int rc = 0;
    for (Py_ssize_t a = 0; a < nnew && rc == 0; a++)
        if (state[a] == 1) {
            const uint64_t *lc = lcms + (size_t)a * nw;
            rc = push_pair(S, mdegree(L, lc), lc, who[a], (int)k);
        }
    free(lcms);
    free(who);
    free(state);
    return rc ? -2 : 0;
}

static int add_basis(State *S)
{
    if (S->nb == S->capb) {
        Py_ssize_t c = S->capb ? 2 * S->capb : 32;
        Poly *b = realloc(S->basis, sizeof(Poly) * c);
        if (!b)
            return -2;
        S->basis = b;
        char *a = realloc(S->active, c);
        if (!a)
            return -2;
        S->active = a;
        S->capb = c;
    }
    poly_monic(&S->work, S->p);
    if (poly_copy(&S->basis[S->nb], S->work.m, S->work.c, S->work.len, S->L->nw) < 0)
        return -2;
    S->active[S->nb++] = 1;
    return pair_update(S);
}

static PyObject *error(int rc)
{
    if (rc == -1) {
        PyObject *mod = PyImport_ImportModule("mech.kernel.buchberger");
        PyObject *exc = mod ? PyObject_GetAttrString(mod, "Overflow") : NULL;
        Py_XDECREF(mod);
        if (exc) {
            PyErr_SetString(exc, "a monomial outgrew its packing");
            Py_DECREF(exc);
        }
        return NULL;
    }
    return PyErr_NoMemory();
}

/* min_degree(st): the least degree of a pair, -1 when none is left */
static PyObject *bba_min_degree(PyObject *self, PyObject *args)
{
    PyObject *cap;
    if (!PyArg_ParseTuple(args, "O", &cap))
        return NULL;
    State *S = get_state(cap);
    if (!S)
        return NULL;
    int d = -1;
    for (Py_ssize_t q = 0; q < S->np; q++)
        if (d < 0 || S->pairs[q].deg < d)
            d = S->pairs[q].deg;
    return PyLong_FromLong(d);
}

static int nw_sort;
static int pair_cmp(const void *x, const void *y)
{
    const Pair *a = x, *b = y;
    int c = mcmp(a->lcm, b->lcm, nw_sort);
    if (c)
        return c;
    if (a->i != b->i)
        return a->i < b->i ? -1 : 1;
    return (a->j > b->j) - (a->j < b->j);
}

/* the S-polynomial of pair a into S->work */
static int spoly(State *S, const Pair *a, int *overflow)
{
    const Layout *L = S->L;
    const int nw = L->nw;
    if (a->j < 0) {
        const Poly *g = &S->gens[a->i];
        if (poly_reserve(&S->work, &S->capwork, g->len, nw) < 0)
            return -2;
        memcpy(S->work.m, g->m, 8 * nw * g->len);
        memcpy(S->work.c, g->c, 4 * g->len);
        S->work.len = g->len;
        return 0;
    }
    const Poly *f = &S->basis[a->i], *g = &S->basis[a->j];
    uint64_t tf[MAXW], tg[MAXW];
    msub(tf, a->lcm, f->m, nw);
    msub(tg, a->lcm, g->m, nw);
    /* t_f * f[1..] into scratch, then minus t_g * g[1..] */
    if (poly_reserve(&S->scratch, &S->capscratch, f->len, nw) < 0)
        return -2;
    for (Py_ssize_t k = 1; k < f->len; k++) {
        madd(S->scratch.m + (size_t)(k - 1) * nw, f->m + (size_t)k * nw, tf, nw);
        if (mguarded(L, S->scratch.m + (size_t)(k - 1) * nw)) {
            *overflow = 1;
            return -1;
        }
        S->scratch.c[k - 1] = f->c[k];
    }
    S->scratch.len = f->len - 1;
    return merge_sub(S, &S->work, &S->capwork, S->scratch.m, S->scratch.c, S->scratch.len, tg, 1, g, 1, overflow);
}

static PyObject *lm_int(const Layout *L, const uint64_t *m)
{
    return _PyLong_FromByteArray((const unsigned char *)m, 8 * L->nw, 1, 0);
}

/* step(st, d, need): the pairs of degree d, top-reduced until `need` new elements are found;
 * returns the new leading monomials (packed integers) */
static PyObject *bba_step(PyObject *self, PyObject *args)
{
    PyObject *cap;
    int d;
    Py_ssize_t need;
    if (!PyArg_ParseTuple(args, "Oin", &cap, &d, &need))
        return NULL;
    State *S = get_state(cap);
    if (!S)
        return NULL;
    const Layout *L = S->L;
    Py_ssize_t nsel = 0, o = 0;
    for (Py_ssize_t q = 0; q < S->np; q++)
        if (S->pairs[q].deg == d)
            nsel++;
    Pair *sel = malloc(sizeof(Pair) * (nsel ? nsel : 1));
    if (!sel)
        return PyErr_NoMemory();
    nsel = 0;
    for (Py_ssize_t q = 0; q < S->np; q++) {
        if (S->pairs[q].deg == d)
            sel[nsel++] = S->pairs[q];
        else
            S->pairs[o++] = S->pairs[q];
    }
    S->np = o;
    nw_sort = L->nw;
    qsort(sel, nsel, sizeof(Pair), pair_cmp);
    PyObject *out = PyList_New(0);
    int overflow = 0, rc = 0;
    for (Py_ssize_t q = 0; q < nsel && need > 0 && out; q++) {
        rc = spoly(S, &sel[q], &overflow);
        if (rc == 0)
            rc = reduce_work(S, S->basis, S->nb, 0, &overflow);
        if (rc < 0)
            break;
        if (S->work.len == 0)
            continue;
        rc = add_basis(S);
        if (rc < 0)
            break;
        need--;
        PyObject *lm = lm_int(L, S->basis[S->nb - 1].m);
        if (!lm || PyList_Append(out, lm) < 0) {
            Py_XDECREF(lm);
            Py_CLEAR(out);
        } else
            Py_DECREF(lm);
    }
    free(sel);
    if (rc < 0) {
        Py_XDECREF(out);
        return error(rc);
    }
    return out;
}

/* map a monomial from layout A to layout B: exponents of B's variables (the first ones) kept */
static void remap(const Layout *A, const Layout *B, uint64_t *out, const uint64_t *m)
{
    memset(out, 0, 8 * B->nw);
    for (int j = 0; j < B->n; j++) {
        uint64_t e = field(m, A->eshift[j], A->ebits);
        if (e)
            maddmul(out, B->units + (size_t)j * B->nw, e, B->nw);
    }
}

static int lm_order(const void *x, const void *y)
{
    const Poly *a = x, *b = y;
    return mcmp(a->m, b->m, nw_sort);
}

/* reduced(st, target): the reduced basis of the active elements mapped to the layout target
 * (None: the state's), by increasing leading monomial: list of (monomials bytes, coefficients
 * bytes).  Each minimal element's tail is reduced by the reduced elements before it. */
static PyObject *bba_reduced(PyObject *self, PyObject *args)
{
    PyObject *cap, *tcap;
    if (!PyArg_ParseTuple(args, "OO", &cap, &tcap))
        return NULL;
    State *S = get_state(cap);
    if (!S)
        return NULL;
    const Layout *A = S->L;
    const Layout *B = tcap == Py_None ? A : PyCapsule_GetPointer(tcap, "bba.layout");
    if (!B)
        return NULL;
    const int nw = B->nw;
    /* the work buffer's capacity counts monomials of the state's width */
    free(S->work.m);
    free(S->work.c);
    S->work.m = NULL;
    S->work.c = NULL;
    S->capwork = 0;
    Py_ssize_t na = 0;
    for (Py_ssize_t k = 0; k < S->nb; k++)
        na += S->active[k];
    Poly *polys = calloc(na ? na : 1, sizeof(Poly));
    Poly *done = calloc(na ? na : 1, sizeof(Poly));
    char *keep = calloc(na ? na : 1, 1);
    if (!polys || !done || !keep) {
        free(polys);
        free(done);
        free(keep);
        return PyErr_NoMemory();
    }
    int rc = 0, overflow = 0;
    Py_ssize_t m = 0, nd = 0;
    for (Py_ssize_t k = 0; k < S->nb && rc == 0; k++) {
        if (!S->active[k])
            continue;
        const Poly *f = &S->basis[k];
        Poly *g = &polys[m++];
        g->len = f->len;
        g->m = malloc(8 * nw * f->len);
        g->c = malloc(4 * f->len);
        if (!g->m || !g->c) {
            rc = -2;
            break;
        }
        memcpy(g->c, f->c, 4 * f->len);
        for (Py_ssize_t t = 0; t < f->len; t++) {
            if (B == A)
                memcpy(g->m + (size_t)t * nw, f->m + (size_t)t * nw, 8 * nw);
            else
                remap(A, B, g->m + (size_t)t * nw, f->m + (size_t)t * A->nw);
        }
    }
    PyObject *out = NULL;
    if (rc == 0) {
        /* minimal elements: no other leading monomial divides (the earlier of equal ones stays) */
        for (Py_ssize_t a = 0; a < m; a++) {
            keep[a] = 1;
            for (Py_ssize_t b = 0; b < m && keep[a]; b++)
                if (b != a && mdivides(B, polys[b].m, polys[a].m)
                    && (mcmp(polys[b].m, polys[a].m, nw) != 0 || b < a))
                    keep[a] = 0;
        }
        Py_ssize_t o = 0;
        for (Py_ssize_t a = 0; a < m; a++) {
            if (keep[a])
                polys[o++] = polys[a];
            else {
                free(polys[a].m);
                free(polys[a].c);
            }
        }
        m = o;
        nw_sort = nw;
        qsort(polys, m, sizeof(Poly), lm_order);
        Layout *saved = S->L;
        S->L = (Layout *)B;
        for (Py_ssize_t a = 0; a < m && rc == 0; a++) {
            Poly *g = &polys[a];
            if (poly_reserve(&S->work, &S->capwork, g->len - 1, nw) < 0) {
                rc = -2;
                break;
            }
            memcpy(S->work.m, g->m + nw, 8 * nw * (g->len - 1));
            memcpy(S->work.c, g->c + 1, 4 * (g->len - 1));
            S->work.len = g->len - 1;
            rc = reduce_work(S, done, nd, 1, &overflow);
            if (rc < 0)
                break;
            Poly *r = &done[nd];
            r->len = S->work.len + 1;
            r->m = malloc(8 * nw * r->len);
            r->c = malloc(4 * r->len);
            if (!r->m || !r->c) {
                free(r->m);
                free(r->c);
                rc = -2;
                break;
            }
            memcpy(r->m, g->m, 8 * nw);
            r->c[0] = g->c[0];
            memcpy(r->m + nw, S->work.m, 8 * nw * S->work.len);
            memcpy(r->c + 1, S->work.c, 4 * S->work.len);
            poly_monic(r, S->p);
            nd++;
        }
        S->L = saved;
        free(S->work.m);
        free(S->work.c);
        S->work.m = NULL;
        S->work.c = NULL;
        S->capwork = 0;
        if (rc == 0) {
            out = PyList_New(nd);
            for (Py_ssize_t a = 0; a < nd && out; a++) {
                PyObject *item = Py_BuildValue("(y#y#)", (const char *)done[a].m, (Py_ssize_t)(8 * nw * done[a].len),
                                               (const char *)done[a].c, (Py_ssize_t)(4 * done[a].len));
                if (!item)
                    Py_CLEAR(out);
                else
                    PyList_SET_ITEM(out, a, item);
            }
        }
    }
    for (Py_ssize_t a = 0; a < m; a++) {
        free(polys[a].m);
        free(polys[a].c);
    }
    for (Py_ssize_t a = 0; a < nd; a++) {
        free(done[a].m);
        free(done[a].c);
    }
    free(polys);
    free(done);
    free(keep);
    if (rc < 0)
        return error(rc);
    return out;
}

/* exponents(layout, monomials bytes): the exponent tuples */
static PyObject *bba_exponents(PyObject *self, PyObject *args)
{
    PyObject *lay;
    Py_buffer mb;
    if (!PyArg_ParseTuple(args, "Oy*", &lay, &mb))
        return NULL;
    Layout *L = PyCapsule_GetPointer(lay, "bba.layout");
    if (!L) {
        PyBuffer_Release(&mb);
        return NULL;
    }
    Py_ssize_t len = mb.len / (8 * L->nw);
    const uint64_t *m = mb.buf;
    PyObject *out = PyList_New(len);
    for (Py_ssize_t t = 0; t < len && out; t++) {
        PyObject *e = PyTuple_New(L->n);
        if (!e) {
            Py_CLEAR(out);
            break;
        }
        for (int j = 0; j < L->n; j++)
            PyTuple_SET_ITEM(e, j, PyLong_FromUnsignedLongLong(field(m + (size_t)t * L->nw, L->eshift[j], L->ebits)));
        PyList_SET_ITEM(out, t, e);
    }
    PyBuffer_Release(&mb);
    return out;
}

static PyMethodDef methods[] = {
    {"layout", bba_layout, METH_VARARGS, "layout(nw, guard, units, eshifts, dshift, ebits): packed monomials."},
    {"state", bba_state, METH_VARARGS, "state(layout, p, gens): generators waiting, no basis yet."},
    {"min_degree", bba_min_degree, METH_VARARGS, "min_degree(st): least degree of a pair, -1 if none."},
    {"step", bba_step, METH_VARARGS, "step(st, d, need): the new leading monomials of degree d."},
    {"reduced", bba_reduced, METH_VARARGS, "reduced(st, target): the reduced basis (bytes pairs)."},
    {"exponents", bba_exponents, METH_VARARGS, "exponents(layout, monomials): exponent tuples."},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_bba", "Hilbert-driven Buchberger modulo p.", -1,
                                    methods};

PyMODINIT_FUNC PyInit__bba(void)
{
    return PyModule_Create(&module);
}
