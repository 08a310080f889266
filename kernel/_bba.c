/* The Hilbert-driven Buchberger algorithm modulo p < 2^50 and the reduction of its basis
 * (kernel/hilbert_compiled.py drives it), the optional extension mech.kernel._bba.
 *
 * Monomials are the packed integers of kernel/monomials.py (``Packing``), split into `nw`
 * little-endian 64-bit words: comparing them word by word from the top compares the monomials
 * in the ordering, a product is a sum, ``a | b`` is ``((b | G) - a) & G == G`` with the guard
 * bits G, and a guard bit set in a product means the packing is too narrow (Overflow).
 * A layout (capsule) holds the words, the guard bits, each variable's exponent field and packed
 * unit (for lcms), and the degree field.
 *
 * A state (capsule) holds the generators, the basis (monic, terms in decreasing order, each with
 * its sugar) and the pairs (sugar, lcm, i, j; j = -1: generator i waiting; for homogeneous input
 * the sugar is the lcm's degree) under the Gebauer-Moeller criteria.  step(st, d, need, defer)
 * takes the pairs of sugar d in increasing (lcm, i, j) order (those marked in `defer` last) and
 * reduces their S-polynomials until `need` new leading monomials are found; the caller (which
 * knows the Hilbert series, or asks for every pair) decides the degree and the need, and defers
 * the pairs a previous prime reduced to zero.  A state's limit bounds the terms summed (TooLong).
 * reduced(st, target) gives the reduced basis of the active elements, their monomials first
 * mapped to the layout `target` (dehomogenization: the exponents of its variables kept, the
 * others dropped).  Beside it: ratlift (the lift's rational reconstruction in 128-bit integers)
 * and hilbert_numerator (kernel/hilbert.py's numerator recursion). */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include "_intmath.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

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
    uint64_t *c; /* below p */
    uint64_t sev; /* reducers: the variables of the leading monomial (bit j mod 64 for x_j) */
} Poly;

typedef struct {
    int deg, i, j; /* deg: the pair's sugar (the lcm's degree for homogeneous input) */
    uint64_t lcm[MAXW];
} Pair;

typedef struct {
    Layout *L;
    PyObject *layout; /* owns L */
    uint64_t p;
    double pinv; /* 1 / p, for mulmod */
    Poly *gens, *basis;
    char *active;
    int *sugar; /* of the basis elements */
    Py_ssize_t ngens, nb, capb;
    long long spent, limit; /* terms summed in reductions; limit 0: none */
    Pair *pairs;
    Py_ssize_t np, capp;
    Poly work;
    Py_ssize_t capwork;
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

/* the variables of a monomial, bit j mod 64 for x_j: a | b needs sev(a) & ~sev(b) == 0 */
static uint64_t msev(const Layout *L, const uint64_t *a)
{
    uint64_t s = 0;
    for (int j = 0; j < L->n; j++)
        if (field(a, L->eshift[j], L->ebits))
            s |= (uint64_t)1 << (j & 63);
    return s;
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
    uint64_t *cc = realloc(f->c, sizeof(uint64_t) * c);
    if (!cc)
        return -1;
    f->c = cc;
    *cap = c;
    return 0;
}

static int poly_copy(Poly *dst, const uint64_t *m, const uint64_t *c, Py_ssize_t len, int nw)
{
    dst->len = len;
    dst->m = malloc(sizeof(uint64_t) * nw * (len ? len : 1));
    dst->c = malloc(sizeof(uint64_t) * (len ? len : 1));
    if (!dst->m || !dst->c)
        return -1;
    memcpy(dst->m, m, sizeof(uint64_t) * nw * len);
    memcpy(dst->c, c, sizeof(uint64_t) * len);
    return 0;
}

/* a b mod p for a, b < p < 2^50: the quotient estimated in double precision is off by less than
 * 1 (relative error below 2^-51 of a value below 2^50), so a b - q p, exact modulo 2^64, lies in
 * [-p, 2p) */
static inline uint64_t mulmod(uint64_t a, uint64_t b, uint64_t p, double pinv)
{
    uint64_t q = (uint64_t)((double)a * (double)b * pinv);
    int64_t r = (int64_t)(a * b - q * p);
    if (r < 0)
        r += (int64_t)p;
    else if (r >= (int64_t)p)
        r -= (int64_t)p;
    return (uint64_t)r;
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
        f->c[k] = (uint64_t)((unsigned __int128)f->c[k] * inv % p);
}

/* A reduction sums polynomials in a geobucket (Yan, 1998): bucket i holds a sorted polynomial of
 * at most 4^(i+1) terms; a polynomial added goes to the first bucket that holds its length, by a
 * merge, and a bucket grown past its size is merged into the next one.  The polynomial under
 * reduction is the sum of the buckets; its leading term is summed from the buckets' first terms,
 * and a reducible one adds -c * t * r[1..] for its reducer r (monic).  A top reduction stops
 * reducing at the first irreducible term (the rest is summed without reduction). */
#define NBUCKETS 24

typedef struct {
    Py_ssize_t head, len; /* the terms head..len-1 */
    Py_ssize_t capm, capc; /* allocated words of monomials (layouts differ in width), coefficients */
    uint64_t *m, *c;
} Bucket;

static Bucket buckets[NBUCKETS];
static int nbuckets;                 /* buckets 0..nbuckets-1 may hold terms */
static Bucket scratch, addend;       /* a merge's output, the polynomial being added */
static uint64_t sum_p;
static double sum_pinv;
static long long sum_terms;          /* terms added since sum_clear */

static int bucket_reserve(Bucket *b, Py_ssize_t n, int nw)
{
    if ((size_t)n * nw > (size_t)b->capm) {
        Py_ssize_t c = 2 * n * nw;
        uint64_t *m = realloc(b->m, 8 * (size_t)c);
        if (!m)
            return -2;
        b->m = m;
        b->capm = c;
    }
    if (n > b->capc) {
        uint64_t *c = realloc(b->c, 8 * (size_t)(2 * n));
        if (!c)
            return -2;
        b->c = c;
        b->capc = 2 * n;
    }
    return 0;
}

/* buckets[i] += the terms m, c (n of them, decreasing) */
static int bucket_add(int i, const uint64_t *m, const uint64_t *c, Py_ssize_t n, int nw)
{
    Bucket *b = &buckets[i];
    Py_ssize_t na = b->len - b->head;
    if (bucket_reserve(&scratch, na + n, nw) < 0)
        return -2;
    const uint64_t *am = b->m + (size_t)b->head * nw, *ac = b->c + b->head;
    Py_ssize_t x = 0, y = 0, o = 0;
    while (x < na && y < n) {
        int cmp = mcmp(am + (size_t)x * nw, m + (size_t)y * nw, nw);
        if (cmp > 0) {
            memcpy(scratch.m + (size_t)o * nw, am + (size_t)x * nw, 8 * nw);
            scratch.c[o++] = ac[x++];
        } else if (cmp < 0) {
            memcpy(scratch.m + (size_t)o * nw, m + (size_t)y * nw, 8 * nw);
            scratch.c[o++] = c[y++];
        } else {
            uint64_t v = ac[x] + c[y];
            if (v >= sum_p)
                v -= sum_p;
            if (v) {
                memcpy(scratch.m + (size_t)o * nw, am + (size_t)x * nw, 8 * nw);
                scratch.c[o++] = v;
            }
            x++;
            y++;
        }
    }
    memcpy(scratch.m + (size_t)o * nw, am + (size_t)x * nw, 8 * nw * (na - x));
    memcpy(scratch.c + o, ac + x, 8 * (na - x));
    o += na - x;
    memcpy(scratch.m + (size_t)o * nw, m + (size_t)y * nw, 8 * nw * (n - y));
    memcpy(scratch.c + o, c + y, 8 * (n - y));
    o += n - y;
    Bucket t = *b;
    *b = scratch;
    b->head = 0;
    b->len = o;
    scratch = t;
    if (i >= nbuckets)
        nbuckets = i + 1;
    return 0;
}

static Py_ssize_t bucket_size(int i)
{
    return (Py_ssize_t)4 << (2 * i);
}

static void sum_clear(uint64_t p, double pinv)
{
    for (int i = 0; i < nbuckets; i++)
        buckets[i].head = buckets[i].len = 0;
    nbuckets = 0;
    sum_p = p;
    sum_pinv = pinv;
    sum_terms = 0;
}

/* the sum += coef * mult * g[pos..] (mult NULL: 1); -1 when a monomial leaves the packing */
static int sum_add(const Layout *L, const Poly *g, Py_ssize_t pos, uint64_t coef, const uint64_t *mult)
{
    const int nw = L->nw;
    Py_ssize_t n = g->len - pos;
    if (n <= 0)
        return 0;
    if (bucket_reserve(&addend, n, nw) < 0)
        return -2;
    for (Py_ssize_t k = 0; k < n; k++) {
        uint64_t *out = addend.m + (size_t)k * nw;
        const uint64_t *in = g->m + (size_t)(pos + k) * nw;
        if (mult) {
            madd(out, in, mult, nw);
            if (mguarded(L, out))
                return -1;
        } else
            memcpy(out, in, 8 * nw);
        addend.c[k] = coef == 1 ? g->c[pos + k] : mulmod(coef, g->c[pos + k], sum_p, sum_pinv);
    }
    sum_terms += n;
    int i = 0;
    while (i < NBUCKETS - 1 && n > bucket_size(i))
        i++;
    if (bucket_add(i, addend.m, addend.c, n, nw) < 0)
        return -2;
    while (i < NBUCKETS - 1 && buckets[i].len - buckets[i].head > bucket_size(i)) {
        Bucket *b = &buckets[i];
        if (bucket_add(i + 1, b->m + (size_t)b->head * nw, b->c + b->head, b->len - b->head, nw) < 0)
            return -2;
        b->head = b->len = 0;
        i++;
    }
    return 0;
}

/* the leading monomial of the sum into m and its coefficient into c, the terms taken out of the
 * buckets; 0 when the sum is empty */
static int sum_top(int nw, uint64_t *m, uint64_t *c)
{
    int best = -1;
    for (int i = 0; i < nbuckets; i++)
        if (buckets[i].head < buckets[i].len
            && (best < 0 || mcmp(buckets[i].m + (size_t)buckets[i].head * nw,
                                 buckets[best].m + (size_t)buckets[best].head * nw, nw) > 0))
            best = i;
    if (best < 0)
        return 0;
    memcpy(m, buckets[best].m + (size_t)buckets[best].head * nw, 8 * nw);
    uint64_t v = 0;
    for (int i = best; i < nbuckets; i++) {
        Bucket *b = &buckets[i];
        if (b->head < b->len && mcmp(b->m + (size_t)b->head * nw, m, nw) == 0) {
            v += b->c[b->head++];
            if (v >= sum_p)
                v -= sum_p;
        }
    }
    *c = v;
    return 1;
}

/* the shortest reducer whose leading monomial divides m (the first of equal lengths), or -1 */
static Py_ssize_t find_reducer(const Layout *L, const Poly *red, Py_ssize_t nred, const uint64_t *m)
{
    Py_ssize_t best = -1;
    const uint64_t not_m = ~msev(L, m);
    for (Py_ssize_t r = 0; r < nred; r++)
        if (!(red[r].sev & not_m) && (best < 0 || red[r].len < red[best].len) && mdivides(L, red[r].m, m))
            best = r;
    return best;
}

/* S->work := the sum, reduced by the reducers: only its top (full = 0) or every term (full = 1) */
static int sum_reduce(State *S, const Poly *red, Py_ssize_t nred, int full)
{
    const Layout *L = S->L;
    const int nw = L->nw;
    const uint64_t p = S->p;
    uint64_t m[MAXW], t[MAXW], c;
    int reducing = 1, rc = 0;
    S->work.len = 0;
    while (sum_top(nw, m, &c)) {
        if (S->limit && S->spent + sum_terms > S->limit)
            return -3;
        if (!c)
            continue;
        if (reducing) {
            Py_ssize_t r = find_reducer(L, red, nred, m);
            if (r >= 0) {
                msub(t, m, red[r].m, nw);
                rc = sum_add(L, &red[r], 1, p - c, t);
                if (rc < 0)
                    return rc;
                continue;
            }
            reducing = full;
        }
        if (poly_reserve(&S->work, &S->capwork, S->work.len + 1, nw) < 0)
            return -2;
        memcpy(S->work.m + (size_t)S->work.len * nw, m, 8 * nw);
        S->work.c[S->work.len++] = c;
    }
    S->spent += sum_terms;
    sum_terms = 0;
    return 0;
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
    free(S->sugar);
    free(S->pairs);
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
    long long limit = 0;
    if (!PyArg_ParseTuple(args, "OKO!|L", &lay, &p, &PyList_Type, &gens, &limit))
        return NULL;
    Layout *L = PyCapsule_GetPointer(lay, "bba.layout");
    if (!L)
        return NULL;
    if (p < 2 || p >= (1ULL << 50)) {
        PyErr_SetString(PyExc_ValueError, "bba.state: p must be below 2^50");
        return NULL;
    }
    State *S = calloc(1, sizeof(State));
    if (!S)
        return PyErr_NoMemory();
    S->L = L;
    S->layout = lay;
    Py_INCREF(lay);
    S->p = p;
    S->pinv = 1.0 / (double)p;
    S->limit = limit;
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
        Py_ssize_t len = cb.len / 8;
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
        int top = 0;
        for (Py_ssize_t t = 0; t < S->gens[k].len; t++) {
            int dt = mdegree(L, S->gens[k].m + (size_t)t * nw);
            if (dt > top)
                top = dt;
        }
        if (push_pair(S, top, S->gens[k].m, (int)k, -1) < 0) {
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
            int dl = mdegree(L, lc), i = who[a];
            int wi = S->sugar[i] + dl - mdegree(L, S->basis[i].m), wk = S->sugar[k] + dl - hdeg;
            rc = push_pair(S, wi > wk ? wi : wk, lc, i, (int)k);
        }
    free(lcms);
    free(who);
    free(state);
    return rc ? -2 : 0;
}

static int add_basis(State *S, int sugar)
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
        int *sg = realloc(S->sugar, sizeof(int) * c);
        if (!sg)
            return -2;
        S->sugar = sg;
        S->capb = c;
    }
    poly_monic(&S->work, S->p);
    if (poly_copy(&S->basis[S->nb], S->work.m, S->work.c, S->work.len, S->L->nw) < 0)
        return -2;
    S->basis[S->nb].sev = msev(S->L, S->work.m);
    S->sugar[S->nb] = sugar;
    S->active[S->nb++] = 1;
    return pair_update(S);
}

/* Raise mech.kernel.buchberger's exception ``name`` with ``message``; NULL. */
static PyObject *raise_buchberger(const char *name, const char *message)
{
    PyObject *mod = PyImport_ImportModule("mech.kernel.buchberger");
    PyObject *exc = mod ? PyObject_GetAttrString(mod, name) : NULL;
    Py_XDECREF(mod);
    if (exc) {
        PyErr_SetString(exc, message);
        Py_DECREF(exc);
    }
    return NULL;
}

static PyObject *error(int rc)
{
    if (rc == -3)
        return raise_buchberger("TooLong", "the compiled Buchberger's budget ran out");
    if (rc == -1)
        return raise_buchberger("Overflow", "a monomial outgrew its packing");
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

/* the sum := the S-polynomial of pair a (or generator i waiting) */
static int spoly_sum(State *S, const Pair *a)
{
    const Layout *L = S->L;
    sum_clear(S->p, S->pinv);
    if (a->j < 0)
        return sum_add(L, &S->gens[a->i], 0, 1, NULL);
    const Poly *f = &S->basis[a->i], *g = &S->basis[a->j];
    uint64_t tf[MAXW], tg[MAXW];
    msub(tf, a->lcm, f->m, L->nw);
    msub(tg, a->lcm, g->m, L->nw);
    int rc = sum_add(L, f, 1, 1, tf);
    return rc ? rc : sum_add(L, g, 1, S->p - 1, tg);
}

static PyObject *lm_int(const Layout *L, const uint64_t *m)
{
    return _PyLong_FromByteArray((const unsigned char *)m, 8 * L->nw, 1, 0);
}

/* step(st, d, need, defer): the pairs of degree d in increasing (lcm, i, j) order, reduced until
 * `need` new elements are found, those whose byte in `defer` (indexed like that order) is set
 * last: a previous prime's zero reductions (any order finds a degree's new leading monomials).
 * Returns (the new leading monomials as packed integers, a byte per pair: 1 if it reduced to
 * zero). */
static PyObject *bba_step(PyObject *self, PyObject *args)
{
    PyObject *cap;
    int d;
    Py_ssize_t need;
    Py_buffer defer = {0};
    if (!PyArg_ParseTuple(args, "Oin|y*", &cap, &d, &need, &defer))
        return NULL;
    State *S = get_state(cap);
    if (!S) {
        PyBuffer_Release(&defer);
        return NULL;
    }
    const Layout *L = S->L;
    Py_ssize_t nsel = 0, o = 0;
    for (Py_ssize_t q = 0; q < S->np; q++)
        if (S->pairs[q].deg == d)
            nsel++;
    Pair *sel = malloc(sizeof(Pair) * (nsel ? nsel : 1));
    char *zeros = calloc(nsel ? nsel : 1, 1);
    if (!sel || !zeros) {
        free(sel);
        free(zeros);
        PyBuffer_Release(&defer);
        return PyErr_NoMemory();
    }
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
    const char *late = defer.len == nsel ? defer.buf : NULL;
    PyObject *lms = PyList_New(0);
    int rc = 0;
    for (int pass = 0; pass < (late ? 2 : 1) && rc == 0; pass++)
        for (Py_ssize_t q = 0; q < nsel && need > 0 && lms; q++) {
            if (late && (late[q] != 0) != pass)
                continue;
            rc = spoly_sum(S, &sel[q]);
            if (rc == 0)
                rc = sum_reduce(S, S->basis, S->nb, 1);
            if (rc < 0)
                break;
            if (S->work.len == 0) {
                zeros[q] = 1;
                continue;
            }
            rc = add_basis(S, d);
            if (rc < 0)
                break;
            need--;
            PyObject *lm = lm_int(L, S->basis[S->nb - 1].m);
            if (!lm || PyList_Append(lms, lm) < 0) {
                Py_XDECREF(lm);
                Py_CLEAR(lms);
            } else
                Py_DECREF(lm);
        }
    PyBuffer_Release(&defer);
    PyObject *out = NULL;
    if (rc < 0)
        error(rc);
    else if (lms)
        out = Py_BuildValue("(Oy#)", lms, zeros, nsel);
    Py_XDECREF(lms);
    free(sel);
    free(zeros);
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
    int rc = 0;
    Py_ssize_t m = 0, nd = 0;
    for (Py_ssize_t k = 0; k < S->nb && rc == 0; k++) {
        if (!S->active[k])
            continue;
        const Poly *f = &S->basis[k];
        Poly *g = &polys[m++];
        g->len = f->len;
        g->m = malloc(8 * nw * f->len);
        g->c = malloc(8 * f->len);
        if (!g->m || !g->c) {
            rc = -2;
            break;
        }
        memcpy(g->c, f->c, 8 * f->len);
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
            sum_clear(S->p, S->pinv);
            rc = sum_add(B, g, 1, 1, NULL);
            if (rc == 0)
                rc = sum_reduce(S, done, nd, 1);
            if (rc < 0)
                break;
            Poly *r = &done[nd];
            r->len = S->work.len + 1;
            r->m = malloc(8 * nw * r->len);
            r->c = malloc(8 * r->len);
            if (!r->m || !r->c) {
                free(r->m);
                free(r->c);
                rc = -2;
                break;
            }
            memcpy(r->m, g->m, 8 * nw);
            r->c[0] = g->c[0];
            memcpy(r->m + nw, S->work.m, 8 * nw * S->work.len);
            memcpy(r->c + 1, S->work.c, 8 * S->work.len);
            poly_monic(r, S->p);
            r->sev = msev(B, r->m);
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
                                               (const char *)done[a].c, (Py_ssize_t)(8 * done[a].len));
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

/* -- the lift to QQ -------------------------------------------------------------------------- */
static u128 isqrt128(u128 x)
{
    u128 r = (u128)sqrtl((long double)x);
    while (r * r > x)
        r--;
    while ((r + 1) * (r + 1) <= x)
        r++;
    return r;
}

/* n/d with n = a d mod M, |n| <= B, 0 < d <= B, gcd(n, d) = 1 (Wang); 0 when none */
static int ratrec128(u128 a, u128 M, u128 B, int64_t *n, int64_t *d)
{
    i128 r0 = (i128)M, r1 = (i128)a, s0 = 0, s1 = 1;
    while (r1 > (i128)B) {
        i128 q = r0 / r1, t;
        t = r0 - q * r1;
        r0 = r1;
        r1 = t;
        t = s0 - q * s1;
        s0 = s1;
        s1 = t;
    }
    i128 as1 = s1 < 0 ? -s1 : s1;
    if (s1 == 0 || as1 > (i128)B || gcd_i64((int64_t)r1, (int64_t)as1) != 1)
        return 0;
    *n = (int64_t)(s1 > 0 ? r1 : -r1);
    *d = (int64_t)as1;
    return 1;
}

/* ratlift(residues: list of bytes (uint64 per coefficient, one per prime), primes: list, check:
 * bytes, q): the rationals n/d (|n|, d <= sqrt(M/2), M the product of the primes, each below
 * 2^50, M below 2^124) with n = r d mod each prime, as (numerators, denominators), if every
 * coefficient has one and they agree with the residues `check` modulo q < 2^50; else None.  A
 * running common denominator makes most coefficients one product per prime. */
static PyObject *bba_ratlift(PyObject *self, PyObject *args)
{
    PyObject *res, *primes;
    Py_buffer check;
    unsigned long long q;
    if (!PyArg_ParseTuple(args, "O!O!y*K", &PyList_Type, &res, &PyList_Type, &primes, &check, &q))
        return NULL;
    Py_ssize_t k = PyList_GET_SIZE(primes), N = check.len / 8;
    PyObject *out = NULL;
    Py_buffer bufs[4];
    int nbuf = 0;
    uint64_t p[4];
    u128 P[5];
    P[0] = 1;
    if (k < 1 || k > 4 || PyList_GET_SIZE(res) != k || q < 2 || q >= (1ULL << 50)) {
        PyErr_SetString(PyExc_ValueError, "ratlift: one to four primes");
        goto done;
    }
    for (Py_ssize_t j = 0; j < k; j++) {
        p[j] = PyLong_AsUnsignedLongLong(PyList_GET_ITEM(primes, j));
        if (PyObject_GetBuffer(PyList_GET_ITEM(res, j), &bufs[j], PyBUF_SIMPLE) < 0)
            goto done;
        nbuf++;
        if (bufs[j].len != check.len || p[j] >= (1ULL << 50) || p[j] < 2 || P[j] > ((((u128)1) << 124) - 1) / p[j]) {
            PyErr_SetString(PyExc_ValueError, "ratlift: bad residues or primes");
            goto done;
        }
        P[j + 1] = P[j] * p[j];
    }
    /* Garner: x = sum t_j P_j with P_j the product of the primes before j */
    uint64_t inv[4];
    double pinv[4], qinv = 1.0 / (double)q;
    for (Py_ssize_t j = 0; j < k; j++) {
        inv[j] = j ? inv_mod((uint64_t)(P[j] % p[j]), p[j]) : 1;
        pinv[j] = 1.0 / (double)p[j];
    }
    const u128 M = P[k], half = M / 2, B = isqrt128(M / 2);
    const uint64_t *r[4];
    for (Py_ssize_t j = 0; j < k; j++)
        r[j] = bufs[j].buf;
    const uint64_t *cq = check.buf;
    PyObject *nums = PyList_New(N), *dens = PyList_New(N);
    if (!nums || !dens) {
        Py_XDECREF(nums);
        Py_XDECREF(dens);
        goto done;
    }
    int64_t den = 1;
    int ok = 1;
    for (Py_ssize_t i = 0; i < N && ok; i++) {
        /* b = r * den mod M, symmetric */
        u128 x = 0;
        for (Py_ssize_t j = 0; j < k; j++) {
            uint64_t v = mulmod(r[j][i] % p[j], (uint64_t)den % p[j], p[j], pinv[j]);
            uint64_t xm = x >> 64 ? (uint64_t)(x % p[j]) : (uint64_t)x % p[j];
            uint64_t t = mulmod(v >= xm ? v - xm : v + p[j] - xm, inv[j], p[j], pinv[j]);
            x += (u128)t * P[j];
        }
        int64_t n, d;
        if (x <= B) {
            n = (int64_t)x;
            d = den;
        } else if (x >= M - B && x > half) {
            n = -(int64_t)(M - x);
            d = den;
        } else {
            u128 a = 0;
            for (Py_ssize_t j = 0; j < k; j++) {
                uint64_t xm = a >> 64 ? (uint64_t)(a % p[j]) : (uint64_t)a % p[j];
                uint64_t rj = r[j][i] % p[j];
                uint64_t t = mulmod(rj >= xm ? rj - xm : rj + p[j] - xm, inv[j], p[j], pinv[j]);
                a += (u128)t * P[j];
            }
            if (!ratrec128(a, M, B, &n, &d)) {
                ok = 0;
                break;
            }
            int64_t g = gcd_i64(den, d);
            u128 l = (u128)(den / g) * (u128)d;
            den = l > B ? d : (int64_t)l;
        }
        /* n / d modulo q against the check residue: n = r d mod q, d invertible */
        uint64_t dq = (uint64_t)d % q;
        if (dq == 0) {
            ok = 0;
            break;
        }
        uint64_t nq = (uint64_t)(n % (int64_t)q + (int64_t)q) % q;
        if (nq != mulmod(cq[i] % q, dq, q, qinv)) {
            ok = 0;
            break;
        }
        PyList_SET_ITEM(nums, i, PyLong_FromLongLong(n));
        PyList_SET_ITEM(dens, i, PyLong_FromLongLong(d));
    }
    if (ok)
        out = Py_BuildValue("(NN)", nums, dens);
    else {
        Py_DECREF(nums);
        Py_DECREF(dens);
        out = Py_None;
        Py_INCREF(out);
    }
done:
    for (int j = 0; j < nbuf; j++)
        PyBuffer_Release(&bufs[j]);
    PyBuffer_Release(&check);
    return out;
}

/* -- the exact check of a lift ------------------------------------------------------------- */
/* Polynomials with integer coefficients in 128 bits; every product and sum is checked for
 * overflow (then the check answers None and the caller does it with Python integers). */
typedef struct {
    Py_ssize_t len;
    uint64_t *m;
    i128 *c;
    uint64_t sev;
} IPoly;

static u128 uabs128(i128 x)
{
    return x < 0 ? -(u128)x : (u128)x;
}

static u128 gcd128(u128 a, u128 b)
{
    while (b) {
        u128 t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* f /= the gcd of its coefficients */
static void ipoly_primitive(IPoly *f)
{
    u128 g = 0;
    for (Py_ssize_t k = 0; k < f->len && g != 1; k++)
        g = gcd128(uabs128(f->c[k]), g);
    if (g > 1)
        for (Py_ssize_t k = 0; k < f->len; k++)
            f->c[k] /= (i128)g;
}

static void ipolys_free(IPoly *f, Py_ssize_t n)
{
    for (Py_ssize_t k = 0; k < n; k++) {
        free(f[k].m);
        free(f[k].c);
    }
    free(f);
}

/* item = (monomials, numerators[, denominators]) (int64 each): f the primitive integer multiple,
 * 1 on overflow, -1 on bad input (exception set), -2 out of memory */
static int ipoly_read(const Layout *L, PyObject *item, IPoly *f)
{
    Py_buffer mb, nb, db = {0};
    int has_den = PyTuple_Check(item) && PyTuple_GET_SIZE(item) == 3;
    if (!PyArg_ParseTuple(item, has_den ? "y*y*y*" : "y*y*", &mb, &nb, &db))
        return -1;
    const int nw = L->nw;
    Py_ssize_t len = nb.len / 8;
    int rc = 0;
    if (mb.len != 8 * nw * len || (has_den && db.len != nb.len) || len == 0) {
        PyErr_SetString(PyExc_ValueError, "bba.in_ideal: bad polynomial");
        rc = -1;
        goto done;
    }
    f->len = len;
    f->m = malloc(8 * nw * len);
    f->c = malloc(sizeof(i128) * len);
    if (!f->m || !f->c) {
        rc = -2;
        goto done;
    }
    memcpy(f->m, mb.buf, 8 * nw * len);
    const int64_t *num = nb.buf, *den = has_den ? db.buf : NULL;
    i128 l = 1; /* the lcm of the denominators */
    for (Py_ssize_t k = 0; den && k < len && rc == 0; k++) {
        if (den[k] <= 0) {
            PyErr_SetString(PyExc_ValueError, "bba.in_ideal: bad denominator");
            rc = -1;
        } else if (__builtin_mul_overflow(l / (i128)gcd128((u128)l, (u128)den[k]), (i128)den[k], &l))
            rc = 1;
    }
    for (Py_ssize_t k = 0; k < len && rc == 0; k++)
        if (__builtin_mul_overflow((i128)num[k], den ? l / den[k] : 1, &f->c[k]))
            rc = 1;
    if (rc == 0) {
        ipoly_primitive(f);
        f->sev = msev(L, f->m);
    }
done:
    PyBuffer_Release(&mb);
    PyBuffer_Release(&nb);
    if (has_den)
        PyBuffer_Release(&db);
    return rc;
}

/* Whether f top-reduces to 0 by the reducers, fraction-free (a step a f - c x^s g cancels the top
 * term with a c = lc(g) f_top / gcd, then the content is removed): 1 yes, 0 no (a top term no
 * leading monomial divides), 2 on overflow (of the coefficients or the packing), -2 out of
 * memory.  f is consumed. */
static int ipoly_reduces_to_zero(const Layout *L, const IPoly *red, Py_ssize_t nred, IPoly *f)
{
    const int nw = L->nw;
    Py_ssize_t cap = 0, fcap = f->len; /* of the buffers om, oc and f's */
    uint64_t *om = NULL, t[MAXW], s[MAXW];
    i128 *oc = NULL;
    int rc = 1;
    while (f->len > 0) {
        Py_ssize_t best = -1;
        const uint64_t not_m = ~msev(L, f->m);
        for (Py_ssize_t k = 0; k < nred; k++)
            if (!(red[k].sev & not_m) && (best < 0 || red[k].len < red[best].len) && mdivides(L, red[k].m, f->m))
                best = k;
        if (best < 0) {
            rc = 0;
            break;
        }
        const IPoly *g = &red[best];
        i128 a = g->c[0], c = f->c[0];
        i128 d = (i128)gcd128(uabs128(a), uabs128(c));
        a /= d;
        c /= d;
        msub(s, f->m, g->m, nw);
        Py_ssize_t need = f->len + g->len;
        if (need > cap) {
            cap = 2 * need;
            uint64_t *m2 = realloc(om, 8 * nw * cap);
            i128 *c2 = m2 ? realloc(oc, sizeof(i128) * cap) : NULL;
            if (m2)
                om = m2;
            if (c2)
                oc = c2;
            if (!m2 || !c2) {
                rc = -2;
                break;
            }
        }
        /* out = a f[1..] - c x^s g[1..], both decreasing */
        Py_ssize_t i = 1, j = 1, n = 0;
        int have = 0;
        while (i < f->len || j < g->len) {
            if (j < g->len && !have) {
                madd(t, g->m + (size_t)j * nw, s, nw);
                if (mguarded(L, t)) {
                    rc = 2;
                    break;
                }
                have = 1;
            }
            int cmp = i >= f->len ? -1 : !have ? 1 : mcmp(f->m + (size_t)i * nw, t, nw);
            i128 v, w;
            const uint64_t *mono;
            if (cmp > 0) {
                if (__builtin_mul_overflow(a, f->c[i], &v)) {
                    rc = 2;
                    break;
                }
                mono = f->m + (size_t)i++ * nw;
            } else {
                if (__builtin_mul_overflow(c, g->c[j], &w)) {
                    rc = 2;
                    break;
                }
                v = -w;
                if (cmp == 0) {
                    i128 u;
                    if (__builtin_mul_overflow(a, f->c[i], &u) || __builtin_add_overflow(u, v, &v)) {
                        rc = 2;
                        break;
                    }
                    i++;
                }
                mono = t;
                j++;
                have = 0;
            }
            if (v) {
                memcpy(om + (size_t)n * nw, mono, 8 * nw);
                oc[n++] = v;
            }
        }
        if (rc != 1)
            break;
        uint64_t *fm = f->m;
        i128 *fc = f->c;
        f->m = om;
        f->c = oc;
        f->len = n;
        om = fm;
        oc = fc;
        Py_ssize_t c2 = cap;
        cap = fcap;
        fcap = c2;
        if (a != 1 && a != -1)
            ipoly_primitive(f);
    }
    free(om);
    free(oc);
    return rc;
}

/* in_ideal(layout, reducers, polys): whether every polynomial top-reduces to 0 by the reducers
 * exactly (True/False), None when 128-bit integers do not suffice.  A reducer is (monomials,
 * numerators, denominators), leading term first; a polynomial (monomials, integer coefficients);
 * all int64 bytes, monomials in the layout's packing. */
static PyObject *bba_in_ideal(PyObject *self, PyObject *args)
{
    PyObject *lay, *reds, *polys;
    if (!PyArg_ParseTuple(args, "OO!O!", &lay, &PyList_Type, &reds, &PyList_Type, &polys))
        return NULL;
    const Layout *L = PyCapsule_GetPointer(lay, "bba.layout");
    if (!L)
        return NULL;
    Py_ssize_t nred = PyList_GET_SIZE(reds);
    IPoly *red = calloc(nred ? nred : 1, sizeof(IPoly));
    if (!red)
        return PyErr_NoMemory();
    int rc = 0; /* 0 going, 1 overflow, -1 error set, -2 memory; answer: */
    int answer = 1;
    for (Py_ssize_t k = 0; k < nred && rc == 0; k++)
        rc = ipoly_read(L, PyList_GET_ITEM(reds, k), &red[k]);
    for (Py_ssize_t k = 0; k < PyList_GET_SIZE(polys) && rc == 0 && answer; k++) {
        IPoly f = {0};
        rc = ipoly_read(L, PyList_GET_ITEM(polys, k), &f);
        if (rc == 0) {
            int z = ipoly_reduces_to_zero(L, red, nred, &f);
            if (z == 2)
                rc = 1;
            else if (z < 0)
                rc = -2;
            else
                answer = z;
        }
        free(f.m);
        free(f.c);
    }
    ipolys_free(red, nred);
    if (rc == -1)
        return NULL;
    if (rc == -2)
        return PyErr_NoMemory();
    if (rc == 1)
        Py_RETURN_NONE;
    return PyBool_FromLong(answer);
}

/* -- Hilbert series numerators -------------------------------------------------------------- */
/* Q(t) of K[x]/M for a monomial ideal M (kernel/hilbert.py's _numerator, the same pivot
 * recursion): exponents as rows of n uint16, series as int64 with overflow checks. */
typedef struct {
    int64_t *c;
    int len;
} Series;

static int series_set(Series *s, int len)
{
    s->c = calloc(len, sizeof(int64_t));
    s->len = len;
    return s->c ? 0 : -2;
}

/* the minimal generators of the k rows (in place), their number */
static int minimal_rows(uint16_t *g, int k, int n)
{
    char *keep = malloc(k ? k : 1);
    if (!keep)
        return -2;
    for (int a = 0; a < k; a++) {
        keep[a] = 1;
        for (int b = 0; b < k && keep[a]; b++) {
            if (b == a)
                continue;
            int div = 1, eq = 1;
            for (int j = 0; j < n && div; j++) {
                if (g[b * n + j] > g[a * n + j])
                    div = 0;
                if (g[b * n + j] != g[a * n + j])
                    eq = 0;
            }
            if (div && (!eq || b < a))
                keep[a] = 0;
        }
    }
    int o = 0;
    for (int a = 0; a < k; a++)
        if (keep[a]) {
            if (o != a)
                memmove(g + o * n, g + a * n, 2 * n);
            o++;
        }
    free(keep);
    return o;
}

static int cmp_u16(const void *a, const void *b)
{
    return (int)*(const uint16_t *)a - (int)*(const uint16_t *)b;
}

/* Q of the ideal of the k minimal rows g (consumed); -1 overflow, -2 memory */
static int numerator(uint16_t *g, int k, int n, Series *out)
{
    if (k == 0) {
        if (series_set(out, 1) < 0)
            return -2;
        out->c[0] = 1;
        return 0;
    }
    int total = 0;
    for (int a = 0; a < k; a++) {
        int d = 0;
        for (int j = 0; j < n; j++)
            d += g[a * n + j];
        if (d == 0) {
            if (series_set(out, 1) < 0)
                return -2;
            return 0;
        }
        total += d;
    }
    int best = 0, bestc = -1;
    for (int j = 0; j < n; j++) {
        int c = 0;
        for (int a = 0; a < k; a++)
            c += g[a * n + j] != 0;
        if (c > bestc) {
            bestc = c;
            best = j;
        }
    }
    if (bestc <= 1) { /* pairwise coprime: prod (1 - t^deg) */
        if (series_set(out, total + 1) < 0)
            return -2;
        out->c[0] = 1;
        int len = 1;
        for (int a = 0; a < k; a++) {
            int d = 0;
            for (int j = 0; j < n; j++)
                d += g[a * n + j];
            for (int t = len - 1; t >= 0; t--)
                if (__builtin_sub_overflow(out->c[t + d], out->c[t], &out->c[t + d]))
                    return -1;
            len += d;
        }
        return 0;
    }
    uint16_t *ex = malloc(2 * k);
    uint16_t *plus = malloc(2 * n * (k + 1)), *colon = malloc(2 * n * (k ? k : 1));
    if (!ex || !plus || !colon) {
        free(ex);
        free(plus);
        free(colon);
        return -2;
    }
    int ne = 0;
    for (int a = 0; a < k; a++)
        if (g[a * n + best])
            ex[ne++] = g[a * n + best];
    qsort(ex, ne, 2, cmp_u16);
    int e = ex[(ne - 1) / 2];
    free(ex);
    int kp = 0;
    for (int a = 0; a < k; a++)
        if (g[a * n + best] < e)
            memcpy(plus + (kp++) * n, g + a * n, 2 * n);
    memset(plus + kp * n, 0, 2 * n);
    plus[kp * n + best] = (uint16_t)e;
    kp++;
    for (int a = 0; a < k; a++) {
        memcpy(colon + a * n, g + a * n, 2 * n);
        colon[a * n + best] = g[a * n + best] > e ? g[a * n + best] - e : 0;
    }
    int rc = 0;
    Series A = {NULL, 0}, B = {NULL, 0};
    kp = minimal_rows(plus, kp, n);
    int kc = minimal_rows(colon, k, n);
    if (kp < 0 || kc < 0)
        rc = -2;
    if (rc == 0)
        rc = numerator(plus, kp, n, &A);
    if (rc == 0)
        rc = numerator(colon, kc, n, &B);
    free(plus);
    free(colon);
    if (rc == 0) {
        int len = A.len > B.len + e ? A.len : B.len + e;
        if (series_set(out, len) < 0)
            rc = -2;
        else {
            for (int t = 0; t < A.len; t++)
                out->c[t] = A.c[t];
            for (int t = 0; t < B.len && rc == 0; t++)
                if (__builtin_add_overflow(out->c[t + e], B.c[t], &out->c[t + e]))
                    rc = -1;
        }
    }
    free(A.c);
    free(B.c);
    return rc;
}

/* hilbert_numerator(monomials, n, divisor=None): Q(t) of K[x]/M as a list (trailing zeros
 * dropped, [0] for the unit ideal), M generated by the monomials, or with a divisor m the colon
 * ideal M : m (generated by the lcm(g, m) / m); OverflowError when a coefficient leaves 64 bits
 * or an exponent 16 bits */
static PyObject *bba_hilbert_numerator(PyObject *self, PyObject *args)
{
    PyObject *mons, *divisor = NULL;
    int n;
    if (!PyArg_ParseTuple(args, "O!i|O!", &PyList_Type, &mons, &n, &PyTuple_Type, &divisor))
        return NULL;
    if (divisor && PyTuple_GET_SIZE(divisor) != n) {
        PyErr_SetString(PyExc_ValueError, "hilbert_numerator: tuples of n exponents");
        return NULL;
    }
    int k = (int)PyList_GET_SIZE(mons);
    uint16_t *g = malloc(2 * (size_t)n * (k ? k : 1));
    if (!g)
        return PyErr_NoMemory();
    for (int a = 0; a < k; a++) {
        PyObject *t = PyList_GET_ITEM(mons, a);
        if (!PyTuple_Check(t) || PyTuple_GET_SIZE(t) != n) {
            free(g);
            PyErr_SetString(PyExc_ValueError, "hilbert_numerator: tuples of n exponents");
            return NULL;
        }
        for (int j = 0; j < n; j++) {
            long v = PyLong_AsLong(PyTuple_GET_ITEM(t, j));
            long w = divisor ? PyLong_AsLong(PyTuple_GET_ITEM(divisor, j)) : 0;
            if (v < 0 || v > 65535 || w < 0) {
                free(g);
                if (!PyErr_Occurred())
                    PyErr_SetString(PyExc_OverflowError, "hilbert_numerator: exponent beyond 16 bits");
                return NULL;
            }
            g[a * n + j] = (uint16_t)(v > w ? v - w : 0); /* the colon (L : x^w) */
        }
    }
    Series out = {NULL, 0};
    int kk = minimal_rows(g, k, n);
    int rc = kk < 0 ? -2 : numerator(g, kk, n, &out);
    free(g);
    if (rc == -1) {
        free(out.c);
        PyErr_SetString(PyExc_OverflowError, "hilbert_numerator: a coefficient beyond 64 bits");
        return NULL;
    }
    if (rc < 0)
        return PyErr_NoMemory();
    int len = out.len;
    while (len > 1 && out.c[len - 1] == 0)
        len--;
    PyObject *res = PyList_New(len);
    for (int t = 0; t < len && res; t++)
        PyList_SET_ITEM(res, t, PyLong_FromLongLong(out.c[t]));
    free(out.c);
    return res;
}

static PyMethodDef methods[] = {
    {"hilbert_numerator", bba_hilbert_numerator, METH_VARARGS, "hilbert_numerator(monomials, n, divisor=None): Q(t) of K[x]/L, or of K[x]/(L : divisor)."},
    {"ratlift", bba_ratlift, METH_VARARGS, "ratlift(residues, primes, check, q): the lift to QQ, checked mod q."},
    {"layout", bba_layout, METH_VARARGS, "layout(nw, guard, units, eshifts, dshift, ebits): packed monomials."},
    {"state", bba_state, METH_VARARGS, "state(layout, p, gens, limit=0): generators waiting, no basis yet."},
    {"min_degree", bba_min_degree, METH_VARARGS, "min_degree(st): least degree of a pair, -1 if none."},
    {"step", bba_step, METH_VARARGS, "step(st, d, need, defer): the new leading monomials of degree d, the zero reductions."},
    {"reduced", bba_reduced, METH_VARARGS, "reduced(st, target): the reduced basis (bytes pairs)."},
    {"exponents", bba_exponents, METH_VARARGS, "exponents(layout, monomials): exponent tuples."},
    {"in_ideal", bba_in_ideal, METH_VARARGS, "in_ideal(layout, reducers, polys): exact top reductions to 0, None on overflow."},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_bba", "Hilbert-driven Buchberger modulo p.", -1,
                                    methods};

PyMODINIT_FUNC PyInit__bba(void)
{
    return PyModule_Create(&module);
}
