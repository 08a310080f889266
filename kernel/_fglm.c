/* FGLM's linear algebra modulo p < 2^31 (kernel/fglm.py ``fglm_modp``): the module
 * mech.kernel._fglm (built with kernel/_fglm_proof.c).
 *
 * fglm_matrices(p, D, n, cols, plan, tidx, tval, M) fills the multiplication matrices M (n*D
 * columns of D entries, uint32) of the quotient by a reduced Groebner basis with standard
 * monomials B (D of them).  Column (a, j) is NF(x_a * B[j]): cols[a*D + j] = r >= 0 says
 * x_a * B[j] = B[r] (a unit vector), r < 0 that it is the border monomial q = -1 - r.  The border
 * monomials come in increasing order of the basis' ordering; plan[3q .. 3q+2] = (kind, x, y):
 * kind 0: q is the leading monomial of a basis element, its normal form is minus its tail, the
 * entries x .. y-1 of (tidx, tval) (B-index, value already negated mod p); kind 1: q = x_x * q'
 * with q' = y an earlier border monomial: NF(q) = sum_c NF(q')_c * NF(x_x * B[c]), where every
 * x_x * B[c] with NF(q')_c != 0 lies below q (B[c] lies below q'), so its column is known.
 * The plan depends on the monomials only (the same at every prime), tval on the prime.
 *
 * fglm_step(p, D, K, M, nfs, piv, slot, mode, a, b): one step of the new staircase's linear
 * algebra.  The state lives in Python-owned arrays of uint32 (array('I')) and int32 (array('i')):
 *   M      n*D columns of D entries: column (i, j) is NF(x_i * B[j]) over the old staircase B;
 *   nfs    the normal forms of the new standard monomials found so far (K vectors of D entries);
 *   piv    their semi-echelon rows, width W = 2*D + 1: D low slots (over B), then slot D + k
 *          records the combination of the k-th new standard monomial;
 *   slot   each row's pivot, the highest nonzero low slot (later rows vanish there).
 * fglm_step(p, D, K, M, nfs, piv, slot, mode, a, b) forms the normal form v of the monomial
 * visited -- mode 0: the unit vector e_a; 1: column (a, b) of M; 2: M_a * nfs[b] -- and
 * reduces (v | e_{D+K}) by the K rows.  If the low slots vanish, the monomial is a new leading
 * monomial: returns the K combination slots (its tail over the new standard monomials).
 * Otherwise v becomes nfs[K], the reduced row (made monic) piv[K] with its pivot, and the
 * result is None.  Accumulation in 64 bits with a reduction every `lim` additions.
 *
 * fglm_replay(p, D, M, steps, tails) repeats at another prime the steps of a conversion done at
 * a first one (the same visits in the same order): steps holds (mode, a, b, leading) for each
 * visit; the tails of the leading monomials go to tails (uint32, D entries each, the K slots of
 * each one followed by zeros).  Returns False as soon as a visit behaves otherwise than at the
 * first prime (the prime is unlucky for this shape or the first one was), else True. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static uint64_t inv_mod(uint64_t a, uint64_t p)
{
    int64_t t = 0, nt = 1, r = (int64_t)p, nr = (int64_t)(a % p);
    while (nr) {
        int64_t q = r / nr, tmp;
        tmp = t - q * nt; t = nt; nt = tmp;
        tmp = r - q * nr; r = nr; nr = tmp;
    }
    return (uint64_t)(t < 0 ? t + (int64_t)p : t);
}

/* The step itself on the raw arrays, x a zeroed scratch vector of W = 2D + 1 entries: returns
 * -1 if the monomial is leading (its tail in x[D .. D+K-1]), else its pivot (the row stored). */
static Py_ssize_t step(uint64_t p, Py_ssize_t D, Py_ssize_t K, const uint32_t *Mv, uint32_t *N, uint32_t *R,
                       int32_t *S, int mode, Py_ssize_t a, Py_ssize_t b, uint64_t *x)
{
    const Py_ssize_t W = 2 * D + 1;
    const uint64_t big = (p - 1) * (p - 1);
    const uint64_t lim = (UINT64_MAX - p) / (big ? big : 1);
    if (mode == 0) {
        x[a] = 1;
    } else if (mode == 1) {
        const uint32_t *col = Mv + (a * D + b) * D;
        for (Py_ssize_t r = 0; r < D; r++)
            x[r] = col[r];
    } else {
        const uint32_t *src = N + b * D;
        uint64_t count = 0;
        for (Py_ssize_t j = 0; j < D; j++) {
            uint64_t c = src[j];
            if (!c)
                continue;
            const uint32_t *col = Mv + (a * D + j) * D;
            for (Py_ssize_t r = 0; r < D; r++)
                x[r] += c * col[r];
            if (++count == lim) {
                for (Py_ssize_t r = 0; r < D; r++)
                    x[r] %= p;
                count = 0;
            }
        }
        for (Py_ssize_t r = 0; r < D; r++)
            x[r] %= p;
    }
    uint32_t *v = N + K * D; /* kept if the monomial is standard */
    for (Py_ssize_t r = 0; r < D; r++)
        v[r] = (uint32_t)x[r];
    x[D + K] = 1;
    uint64_t count = 0;
    for (Py_ssize_t k = 0; k < K; k++) {
        const Py_ssize_t s = S[k];
        uint64_t c = x[s] % p;
        if (!c)
            continue;
        c = p - c;
        const uint32_t *y = R + k * W;
        for (Py_ssize_t t = 0; t <= s; t++)
            x[t] += c * y[t];
        for (Py_ssize_t t = D; t <= D + k; t++)
            x[t] += c * y[t];
        if (++count == lim) {
            for (Py_ssize_t t = 0; t < W; t++)
                x[t] %= p;
            count = 0;
        }
    }
    Py_ssize_t s0 = -1;
    for (Py_ssize_t t = 0; t < W; t++) {
        x[t] %= p;
        if (t < D && x[t])
            s0 = t;
    }
    if (s0 >= 0) {
        const uint64_t inv = inv_mod(x[s0], p);
        uint32_t *row = R + K * W;
        for (Py_ssize_t t = 0; t < W; t++)
            row[t] = (uint32_t)(x[t] * inv % p);
        S[K] = (int32_t)s0;
    }
    return s0;
}

static PyObject *fglm_step(PyObject *self, PyObject *args)
{
    unsigned long long p_;
    Py_ssize_t D, K;
    int mode;
    Py_ssize_t a, b;
    Py_buffer M, nfs, piv, slot;
    if (!PyArg_ParseTuple(args, "Knnw*w*w*w*inn", &p_, &D, &K, &M, &nfs, &piv, &slot, &mode, &a, &b))
        return NULL;
    const Py_ssize_t W = 2 * D + 1;
    PyObject *result = NULL;
    if (K > D || (Py_ssize_t)(nfs.len / 4) < (K + 1) * D || (Py_ssize_t)(piv.len / 4) < (K + 1) * W
        || (Py_ssize_t)(slot.len / 4) < K + 1) {
        PyErr_SetString(PyExc_ValueError, "fglm_step: arrays too small");
        goto done;
    }
    uint64_t *x = calloc((size_t)W, sizeof(uint64_t));
    if (!x) {
        PyErr_NoMemory();
        goto done;
    }
    if (step(p_, D, K, M.buf, nfs.buf, piv.buf, slot.buf, mode, a, b, x) < 0) {
        result = PyList_New(K);
        if (result)
            for (Py_ssize_t k = 0; k < K; k++) {
                PyObject *o = PyLong_FromUnsignedLongLong(x[D + k]);
                if (!o) {
                    Py_CLEAR(result);
                    break;
                }
                PyList_SET_ITEM(result, k, o);
            }
    } else {
        Py_INCREF(Py_None);
        result = Py_None;
    }
    free(x);
done:
    PyBuffer_Release(&M);
    PyBuffer_Release(&nfs);
    PyBuffer_Release(&piv);
    PyBuffer_Release(&slot);
    return result;
}

static PyObject *fglm_matrices(PyObject *self, PyObject *args)
{
    unsigned long long p_;
    Py_ssize_t D, n;
    Py_buffer cols, plan, tidx, tval, M;
    if (!PyArg_ParseTuple(args, "Knny*y*y*y*w*", &p_, &D, &n, &cols, &plan, &tidx, &tval, &M))
        return NULL;
    const uint64_t p = p_;
    const int32_t *C = cols.buf, *P = plan.buf, *I = tidx.buf;
    const uint32_t *V = tval.buf;
    uint32_t *Mv = M.buf;
    const Py_ssize_t Q = plan.len / 12, T = tidx.len / 4;
    PyObject *result = NULL;
    uint32_t *F = NULL; /* the border monomials' normal forms, Q vectors of D entries */
    uint64_t *x = NULL;
    if (cols.len / 4 < n * D || M.len / 4 < n * D * D || tval.len / 4 < T) {
        PyErr_SetString(PyExc_ValueError, "fglm_matrices: arrays too small");
        goto done;
    }
    F = calloc((size_t)(Q * D + 1), sizeof(uint32_t));
    x = calloc((size_t)(D + 1), sizeof(uint64_t));
    if (!F || !x) {
        PyErr_NoMemory();
        goto done;
    }
    const uint64_t big = (p - 1) * (p - 1);
    const uint64_t lim = (UINT64_MAX - p) / (big ? big : 1);
    for (Py_ssize_t q = 0; q < Q; q++) {
        const int32_t kind = P[3 * q], u = P[3 * q + 1], w = P[3 * q + 2];
        uint32_t *f = F + q * D;
        if (kind == 0) {
            if (u < 0 || w > T || u > w)
                goto bad;
            for (Py_ssize_t e = u; e < w; e++) {
                if (I[e] < 0 || I[e] >= D)
                    goto bad;
                f[I[e]] = V[e];
            }
            continue;
        }
        if (u < 0 || u >= n || w < 0 || w >= q)
            goto bad;
        const uint32_t *g = F + (Py_ssize_t)w * D;
        memset(x, 0, (size_t)D * sizeof(uint64_t));
        uint64_t count = 0;
        for (Py_ssize_t c = 0; c < D; c++) {
            const uint64_t v = g[c];
            if (!v)
                continue;
            const int32_t r = C[u * D + c];
            if (r >= 0) {
                if (r >= D)
                    goto bad;
                x[r] += v;
            } else {
                if (-1 - r >= q)
                    goto bad;
                const uint32_t *h = F + (Py_ssize_t)(-1 - r) * D;
                for (Py_ssize_t s = 0; s < D; s++)
                    x[s] += v * h[s];
            }
            if (++count == lim) {
                for (Py_ssize_t s = 0; s < D; s++)
                    x[s] %= p;
                count = 0;
            }
        }
        for (Py_ssize_t s = 0; s < D; s++)
            f[s] = (uint32_t)(x[s] % p);
    }
    for (Py_ssize_t c = 0; c < n * D; c++) {
        uint32_t *col = Mv + c * D;
        const int32_t r = C[c];
        if (r >= 0) {
            if (r >= D)
                goto bad;
            memset(col, 0, (size_t)D * sizeof(uint32_t));
            col[r] = 1;
        } else {
            if (-1 - r >= Q)
                goto bad;
            memcpy(col, F + (Py_ssize_t)(-1 - r) * D, (size_t)D * sizeof(uint32_t));
        }
    }
    Py_INCREF(Py_None);
    result = Py_None;
    goto done;
bad:
    PyErr_SetString(PyExc_ValueError, "fglm_matrices: the plan is inconsistent");
done:
    free(F);
    free(x);
    PyBuffer_Release(&cols);
    PyBuffer_Release(&plan);
    PyBuffer_Release(&tidx);
    PyBuffer_Release(&tval);
    PyBuffer_Release(&M);
    return result;
}

static PyObject *fglm_replay(PyObject *self, PyObject *args)
{
    unsigned long long p_;
    Py_ssize_t D;
    Py_buffer M, steps, tails;
    if (!PyArg_ParseTuple(args, "Kny*y*w*", &p_, &D, &M, &steps, &tails))
        return NULL;
    const Py_ssize_t W = 2 * D + 1, S = steps.len / 16;
    const int32_t *st = steps.buf;
    uint32_t *out = tails.buf;
    PyObject *result = NULL;
    uint32_t *N = calloc((size_t)(D * (D + 1)), sizeof(uint32_t));
    uint32_t *R = calloc((size_t)(W * (D + 1)), sizeof(uint32_t));
    int32_t *slot = calloc((size_t)(D + 1), sizeof(int32_t));
    uint64_t *x = malloc((size_t)W * sizeof(uint64_t));
    if (!N || !R || !slot || !x) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t K = 0, L = 0;
    int same = 1;
    for (Py_ssize_t i = 0; i < S && same; i++) {
        const int mode = st[4 * i], leading = st[4 * i + 3];
        const Py_ssize_t a = st[4 * i + 1], b = st[4 * i + 2];
        if (mode < 0 || mode > 2 || a < 0 || b < 0 || (mode == 0 && a >= D) || (mode == 1 && b >= D)
            || (mode == 2 && b >= K) || (mode > 0 && (Py_ssize_t)(M.len / 4) < (a + 1) * D * D)
            || (leading && (Py_ssize_t)(tails.len / 4) < (L + 1) * D)) {
            PyErr_SetString(PyExc_ValueError, "fglm_replay: a step out of range");
            goto done;
        }
        memset(x, 0, (size_t)W * sizeof(uint64_t));
        const Py_ssize_t s0 = step(p_, D, K, M.buf, N, R, slot, mode, a, b, x);
        if ((s0 < 0) != (leading != 0)) {
            same = 0;
        } else if (s0 < 0) {
            uint32_t *t = out + L * D;
            for (Py_ssize_t k = 0; k < D; k++)
                t[k] = k < K ? (uint32_t)x[D + k] : 0;
            L++;
        } else if (++K > D) {
            same = 0;
        }
    }
    result = PyBool_FromLong(same);
done:
    free(N);
    free(R);
    free(slot);
    free(x);
    PyBuffer_Release(&M);
    PyBuffer_Release(&steps);
    PyBuffer_Release(&tails);
    return result;
}

/* An open-addressing table of packed monomials (nonzero keys stored as key + 1). */
typedef struct {
    uint64_t *keys;
    int64_t *vals;
    size_t mask;
} Table;

static int table_init(Table *t, size_t want)
{
    size_t size = 16;
    while (size < 2 * want + 2)
        size <<= 1;
    t->keys = calloc(size, sizeof(uint64_t));
    t->vals = calloc(size, sizeof(int64_t));
    t->mask = size - 1;
    return t->keys && t->vals;
}

static int64_t *table_slot(Table *t, uint64_t key, int insert)
{
    size_t h = (size_t)((key + 1) * 0x9E3779B97F4A7C15ULL >> 17) & t->mask;
    while (t->keys[h]) {
        if (t->keys[h] == key + 1)
            return t->vals + h;
        h = (h + 1) & t->mask;
    }
    if (!insert)
        return NULL;
    t->keys[h] = key + 1;
    return t->vals + h;
}

/* A node of the walk's heap: a monomial x_i * stairs[k], its key W e (n entries) kept apart. */
typedef struct {
    uint64_t mono;
    int32_t i, k;
} Node;

static int key_less(const int64_t *a, const int64_t *b, Py_ssize_t n)
{
    for (Py_ssize_t r = 0; r < n; r++)
        if (a[r] != b[r])
            return a[r] < b[r];
    return 0;
}

/* fglm_walk(p, D, n, w, W, M, codes_keys, codes_vals, steps) runs fglm_modp's visits in C:
 * monomials packed with w bits a variable, visited in increasing order of the keys W e (W the
 * target's nonnegative n x n weight matrix, int64 row by row); codes_keys/codes_vals say which
 * packed monomials are B[j] (value j) or the border monomial x_a * B[j] (value D + a*D + j).
 * Fills steps (4 int32 a visit) and returns (stairs, stair_from, lms, lm_from, tails, visits) with
 * packed monomials, flat (i, k) pairs and the tails as bytes (L rows of D uint32), or None when
 * the new staircase outgrows D (an unlucky prime). */
static PyObject *fglm_walk(PyObject *self, PyObject *args)
{
    unsigned long long p_;
    Py_ssize_t D, n, w;
    Py_buffer Wb, M, ck, cv, steps;
    if (!PyArg_ParseTuple(args, "Knnny*y*y*y*w*", &p_, &D, &n, &w, &Wb, &M, &ck, &cv, &steps))
        return NULL;
    const int64_t *W = Wb.buf;
    const uint64_t *CK = ck.buf;
    const int64_t *CV = cv.buf;
    const Py_ssize_t ncodes = ck.len / 8, cap = n * (D + 1) + 1; /* visits at most */
    const Py_ssize_t Wd = 2 * D + 1;
    PyObject *result = NULL;
    Table codes = {0}, marks = {0}; /* marks: 1 seen, 2 inside the new leading ideal */
    Node *nodes = NULL;
    int64_t *keys = NULL;
    Py_ssize_t *heap = NULL;
    uint32_t *N = NULL, *R = NULL;
    int32_t *slot = NULL;
    uint64_t *x = NULL, *st = NULL, *lm = NULL;
    int32_t *stf = NULL, *lmf = NULL;
    uint32_t *tl = NULL; /* the tails, tcap rows of D */
    Py_ssize_t tcap = 0;
    if (Wb.len / 8 < n * n || cv.len / 8 < ncodes || n * w > 64 || (Py_ssize_t)(steps.len / 16) < cap || (Py_ssize_t)(M.len / 4) < n * D * D) {
        PyErr_SetString(PyExc_ValueError, "fglm_walk: arrays too small");
        goto done;
    }
    nodes = malloc((size_t)cap * sizeof(Node));
    keys = malloc((size_t)(cap * n + 1) * sizeof(int64_t));
    heap = malloc((size_t)cap * sizeof(Py_ssize_t));
    N = calloc((size_t)(D * (D + 1) + 1), sizeof(uint32_t));
    R = calloc((size_t)(Wd * (D + 1)), sizeof(uint32_t));
    slot = calloc((size_t)(D + 1), sizeof(int32_t));
    x = malloc((size_t)Wd * sizeof(uint64_t));
    st = malloc((size_t)(D + 1) * sizeof(uint64_t));
    stf = malloc((size_t)(2 * D + 2) * sizeof(int32_t));
    lm = malloc((size_t)cap * sizeof(uint64_t));
    lmf = malloc((size_t)(2 * cap) * sizeof(int32_t));
    if (!nodes || !keys || !heap || !N || !R || !slot || !x || !st || !stf || !lm || !lmf
        || !table_init(&codes, (size_t)ncodes) || !table_init(&marks, (size_t)cap)) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t c = 0; c < ncodes; c++)
        *table_slot(&codes, CK[c], 1) = CV[c];
    const uint64_t field = (w >= 64) ? ~0ULL : ((1ULL << w) - 1);
    Py_ssize_t used = 0, size = 0, K = 0, L = 0, visits = 0;
    /* push 1 */
    nodes[0].mono = 0;
    nodes[0].i = nodes[0].k = -1;
    memset(keys, 0, (size_t)n * sizeof(int64_t));
    heap[size++] = used++;
    *table_slot(&marks, 0, 1) = 1;
    while (size) {
        const Py_ssize_t top = heap[0];
        heap[0] = heap[--size];
        for (Py_ssize_t h = 0;;) { /* sift down */
            Py_ssize_t l = 2 * h + 1, m = h;
            if (l < size && key_less(keys + heap[l] * n, keys + heap[m] * n, n))
                m = l;
            if (l + 1 < size && key_less(keys + heap[l + 1] * n, keys + heap[m] * n, n))
                m = l + 1;
            if (m == h)
                break;
            Py_ssize_t tmp = heap[h]; heap[h] = heap[m]; heap[m] = tmp;
            h = m;
        }
        const uint64_t mono = nodes[top].mono;
        const int32_t i = nodes[top].i, k = nodes[top].k;
        int inside = 0;
        for (Py_ssize_t j = 0; j < n && !inside; j++) {
            if (j == i || !((mono >> (w * j)) & field))
                continue;
            int64_t *v = table_slot(&marks, mono - (1ULL << (w * j)), 0);
            inside = v && (*v & 2);
        }
        if (inside) {
            *table_slot(&marks, mono, 1) |= 2;
            continue;
        }
        int mode;
        Py_ssize_t a, b;
        const int64_t *code = table_slot(&codes, mono, 0);
        if (code && *code < D) {
            mode = 0, a = *code, b = 0;
        } else if (code) {
            mode = 1, a = (*code - D) / D, b = (*code - D) % D;
        } else {
            if (i < 0 || k < 0 || k >= K) {
                PyErr_SetString(PyExc_ValueError, "fglm_walk: a monomial neither in B nor on the border");
                goto done;
            }
            mode = 2, a = i, b = k;
        }
        memset(x, 0, (size_t)Wd * sizeof(uint64_t));
        const Py_ssize_t s0 = step(p_, D, K, M.buf, N, R, slot, mode, a, b, x);
        int32_t *rec = (int32_t *)steps.buf + 4 * visits++;
        rec[0] = mode, rec[1] = (int32_t)a, rec[2] = (int32_t)b, rec[3] = s0 < 0;
        if (s0 < 0) {
            *table_slot(&marks, mono, 1) |= 2;
            if (L == tcap) {
                tcap = 2 * tcap + 8;
                uint32_t *more = realloc(tl, (size_t)(tcap * D) * sizeof(uint32_t));
                if (!more) {
                    PyErr_NoMemory();
                    goto done;
                }
                tl = more;
            }
            uint32_t *t = tl + L * D;
            for (Py_ssize_t c = 0; c < D; c++)
                t[c] = c < K ? (uint32_t)x[D + c] : 0;
            lm[L] = mono, lmf[2 * L] = i, lmf[2 * L + 1] = k;
            L++;
            continue;
        }
        if (K == D) { /* the new staircase outgrows the old one: an unlucky prime */
            Py_INCREF(Py_None);
            result = Py_None;
            goto done;
        }
        st[K] = mono, stf[2 * K] = i, stf[2 * K + 1] = k;
        K++;
        for (Py_ssize_t j = 0; j < n; j++) {
            const uint64_t y = mono + (1ULL << (w * j));
            if (((y >> (w * j)) & field) == 0 || used >= cap) {
                PyErr_SetString(PyExc_ValueError, "fglm_walk: an exponent outgrows its digits");
                goto done;
            }
            int64_t *v = table_slot(&marks, y, 1);
            if (*v & 1)
                continue;
            *v |= 1;
            Node *nd = nodes + used;
            nd->mono = y, nd->i = (int32_t)j, nd->k = (int32_t)(K - 1);
            int64_t *ky = keys + used * n;
            for (Py_ssize_t r = 0; r < n; r++)
                ky[r] = keys[top * n + r] + W[r * n + j];
            Py_ssize_t h = size++; /* sift up */
            heap[h] = used++;
            while (h) {
                Py_ssize_t parent = (h - 1) / 2;
                if (!key_less(keys + heap[h] * n, keys + heap[parent] * n, n))
                    break;
                Py_ssize_t tmp = heap[h]; heap[h] = heap[parent]; heap[parent] = tmp;
                h = parent;
            }
        }
    }
    {
        PyObject *s_list = PyList_New(K), *sf = PyList_New(2 * K), *l_list = PyList_New(L), *lf = PyList_New(2 * L);
        if (!s_list || !sf || !l_list || !lf) {
            Py_XDECREF(s_list); Py_XDECREF(sf); Py_XDECREF(l_list); Py_XDECREF(lf);
            goto done;
        }
        for (Py_ssize_t c = 0; c < K; c++) {
            PyList_SET_ITEM(s_list, c, PyLong_FromUnsignedLongLong(st[c]));
            PyList_SET_ITEM(sf, 2 * c, PyLong_FromLong(stf[2 * c]));
            PyList_SET_ITEM(sf, 2 * c + 1, PyLong_FromLong(stf[2 * c + 1]));
        }
        for (Py_ssize_t c = 0; c < L; c++) {
            PyList_SET_ITEM(l_list, c, PyLong_FromUnsignedLongLong(lm[c]));
            PyList_SET_ITEM(lf, 2 * c, PyLong_FromLong(lmf[2 * c]));
            PyList_SET_ITEM(lf, 2 * c + 1, PyLong_FromLong(lmf[2 * c + 1]));
        }
        if (PyErr_Occurred()) { /* an int not made: lists with holes */
            Py_DECREF(s_list); Py_DECREF(sf); Py_DECREF(l_list); Py_DECREF(lf);
            goto done;
        }
        result = Py_BuildValue("(NNNNy#n)", s_list, sf, l_list, lf, (char *)(tl ? tl : (uint32_t *)st),
                               (Py_ssize_t)(L * D * 4), visits);
    }
done:
    free(codes.keys); free(codes.vals); free(marks.keys); free(marks.vals);
    free(nodes); free(keys); free(heap); free(N); free(R); free(slot); free(x);
    free(st); free(stf); free(lm); free(lmf); free(tl);
    PyBuffer_Release(&Wb);
    PyBuffer_Release(&M);
    PyBuffer_Release(&ck);
    PyBuffer_Release(&cv);
    PyBuffer_Release(&steps);
    return result;
}

/* fglm_plan(n, w, W, B, terms, offsets): the border's plan of fglm_matrices (kernel/fglm.py
 * ``Border``) for a reduced basis whose elements have the terms offsets[k] .. offsets[k+1]-1 of
 * terms (n int32 exponents each) and standard monomials B (D of them, increasing), monomials
 * packed with w bits a variable, W the basis ordering's nonnegative weight matrix.  The leading
 * term of an element is its one term outside B.  Returns (cols, plan, tidx, tsrc, code_keys,
 * code_values) as bytes -- tsrc: each tail entry's position among the terms -- or None when the
 * basis is not reduced for B (then the caller takes another path). */
static const int64_t *sort_keys;
static Py_ssize_t sort_n;

static int by_key(const void *a, const void *b)
{
    const int64_t *x = sort_keys + *(const Py_ssize_t *)a * sort_n, *y = sort_keys + *(const Py_ssize_t *)b * sort_n;
    for (Py_ssize_t r = 0; r < sort_n; r++)
        if (x[r] != y[r])
            return x[r] < y[r] ? -1 : 1;
    return 0;
}

static PyObject *fglm_plan(PyObject *self, PyObject *args)
{
    Py_ssize_t n, w;
    Py_buffer Wb, Bb, tb, ob;
    if (!PyArg_ParseTuple(args, "nny*y*y*y*", &n, &w, &Wb, &Bb, &tb, &ob))
        return NULL;
    const int64_t *W = Wb.buf, *O = ob.buf;
    const int32_t *BE = Bb.buf, *TE = tb.buf;
    const Py_ssize_t D = n > 0 ? Bb.len / 4 / n : 0, L = ob.len / 8 - 1, T = n > 0 ? tb.len / 4 / n : 0;
    PyObject *result = NULL;
    Table index = {0}, border = {0};
    uint64_t *Bp = NULL, *bp = NULL;
    int32_t *cols = NULL, *ba = NULL, *bj = NULL, *plan = NULL, *tidx = NULL, *tsrc = NULL, *lead = NULL;
    int64_t *keys = NULL, *codes = NULL;
    Py_ssize_t *sorted = NULL, *pos = NULL, nb = 0, nt = 0;
    int reduced = 1;
    if (n <= 0 || n * w > 64 || w <= 0 || Wb.len / 8 < n * n || L < 0 || D <= 0) {
        PyErr_SetString(PyExc_ValueError, "fglm_plan: inconsistent arguments");
        goto done;
    }
    const uint64_t field = (w >= 64) ? ~0ULL : ((1ULL << w) - 1);
    const Py_ssize_t cap = n * D;
    Bp = malloc((size_t)D * sizeof(uint64_t));
    bp = malloc((size_t)cap * sizeof(uint64_t));
    cols = malloc((size_t)cap * sizeof(int32_t));
    ba = malloc((size_t)cap * sizeof(int32_t));
    bj = malloc((size_t)cap * sizeof(int32_t));
    plan = malloc((size_t)(3 * cap + 1) * sizeof(int32_t));
    tidx = malloc((size_t)(T + 1) * sizeof(int32_t));
    tsrc = malloc((size_t)(T + 1) * sizeof(int32_t));
    lead = malloc((size_t)cap * sizeof(int32_t));
    keys = malloc((size_t)(cap * n + 1) * sizeof(int64_t));
    codes = malloc((size_t)(D + cap) * 2 * sizeof(int64_t));
    sorted = malloc((size_t)cap * sizeof(Py_ssize_t));
    pos = malloc((size_t)cap * sizeof(Py_ssize_t));
    if (!Bp || !bp || !cols || !ba || !bj || !plan || !tidx || !tsrc || !lead || !keys || !codes || !sorted || !pos
        || !table_init(&index, (size_t)D) || !table_init(&border, (size_t)cap)) {
        PyErr_NoMemory();
        goto done;
    }
    /* pack a monomial; 0 if an exponent does not fit its digit */
#define PACK(e, out)                                                    \
    do {                                                                \
        uint64_t v_ = 0;                                                \
        for (Py_ssize_t j_ = 0; j_ < n; j_++) {                         \
            if ((e)[j_] < 0 || (uint64_t)(e)[j_] >= field)              \
                reduced = 0;                                            \
            v_ += (uint64_t)(e)[j_] << (w * j_);                        \
        }                                                               \
        (out) = v_;                                                     \
    } while (0)
    for (Py_ssize_t j = 0; j < D; j++) {
        PACK(BE + j * n, Bp[j]);
        *table_slot(&index, Bp[j], 1) = j;
    }
    if (!reduced)
        goto refuse;
    for (Py_ssize_t a = 0; a < n; a++)
        for (Py_ssize_t j = 0; j < D; j++) {
            const uint64_t u = Bp[j] + (1ULL << (w * a));
            if ((((Bp[j] >> (w * a)) & field) + 1) >= field)
                goto refuse;
            int64_t *r = table_slot(&index, u, 0);
            if (r) {
                cols[a * D + j] = (int32_t)*r;
                continue;
            }
            int64_t *v = table_slot(&border, u, 1);
            if (!*v) { /* new on the border: ids from 1 in the table */
                *v = ++nb;
                bp[nb - 1] = u, ba[nb - 1] = (int32_t)a, bj[nb - 1] = (int32_t)j, lead[nb - 1] = -1;
                int64_t *k = keys + (nb - 1) * n;
                for (Py_ssize_t r2 = 0; r2 < n; r2++) {
                    int64_t s = W[r2 * n + a];
                    for (Py_ssize_t c = 0; c < n; c++)
                        s += W[r2 * n + c] * BE[j * n + c];
                    k[r2] = s;
                }
            }
            cols[a * D + j] = (int32_t)(-*v); /* -(id + 1) for now */
        }
    for (Py_ssize_t q = 0; q < nb; q++)
        sorted[q] = q;
    sort_keys = keys, sort_n = n;
    qsort(sorted, (size_t)nb, sizeof(Py_ssize_t), by_key);
    for (Py_ssize_t q = 0; q < nb; q++)
        pos[sorted[q]] = q;
    for (Py_ssize_t c = 0; c < cap; c++)
        if (cols[c] < 0)
            cols[c] = (int32_t)(-1 - pos[-cols[c] - 1]);
    /* the elements: one term outside B each (on the border, leading no other element), the rest
     * their tails */
    int64_t *toff = codes; /* borrowed until the codes are written: L + 1 entries */
    if (L + 1 > 2 * (D + cap))
        goto refuse;
    for (Py_ssize_t k = 0; k < L; k++) {
        const Py_ssize_t a = O[k], b = O[k + 1];
        if (a < 0 || b < a || b > T)
            goto refuse;
        Py_ssize_t outside = -1;
        toff[k] = nt;
        for (Py_ssize_t t = a; t < b; t++) {
            uint64_t u;
            PACK(TE + t * n, u);
            if (!reduced)
                goto refuse;
            int64_t *r = table_slot(&index, u, 0);
            if (r) {
                tidx[nt] = (int32_t)*r, tsrc[nt] = (int32_t)t;
                nt++;
            } else {
                int64_t *v = table_slot(&border, u, 0);
                if (outside >= 0 || !v || lead[*v - 1] >= 0)
                    goto refuse;
                outside = *v - 1;
                lead[outside] = (int32_t)k;
            }
        }
        if (outside < 0)
            goto refuse;
    }
    toff[L] = nt;
    for (Py_ssize_t q = 0; q < nb; q++) {
        const Py_ssize_t id = sorted[q];
        int32_t *pl = plan + 3 * q;
        if (lead[id] >= 0) {
            pl[0] = 0, pl[1] = (int32_t)toff[lead[id]], pl[2] = (int32_t)toff[lead[id] + 1];
            continue;
        }
        const uint64_t u = bp[id];
        Py_ssize_t i = 0;
        for (; i < n; i++) {
            if (!((u >> (w * i)) & field))
                continue;
            int64_t *v = table_slot(&border, u - (1ULL << (w * i)), 0);
            if (v) {
                pl[0] = 1, pl[1] = (int32_t)i, pl[2] = (int32_t)pos[*v - 1];
                break;
            }
        }
        if (i == n) /* a minimal generator of the leading ideal leads no element */
            goto refuse;
    }
    {
        uint64_t *ck = (uint64_t *)codes;
        int64_t *cv = codes + D + nb;
        for (Py_ssize_t j = 0; j < D; j++)
            ck[j] = Bp[j], cv[j] = j;
        for (Py_ssize_t id = 0; id < nb; id++)
            ck[D + id] = bp[id], cv[D + id] = D + (int64_t)ba[id] * D + bj[id];
        result = Py_BuildValue("(y#y#y#y#y#y#)", (char *)cols, (Py_ssize_t)(cap * 4), (char *)plan,
                               (Py_ssize_t)(nb * 12),
                               (char *)tidx, (Py_ssize_t)(nt * 4), (char *)tsrc, (Py_ssize_t)(nt * 4),
                               (char *)ck, (Py_ssize_t)((D + nb) * 8), (char *)cv, (Py_ssize_t)((D + nb) * 8));
    }
    goto done;
#undef PACK
refuse:
    Py_INCREF(Py_None);
    result = Py_None;
done:
    free(index.keys); free(index.vals); free(border.keys); free(border.vals);
    free(Bp); free(bp); free(cols); free(ba); free(bj); free(plan); free(tidx); free(tsrc); free(lead);
    free(keys); free(codes); free(sorted); free(pos);
    PyBuffer_Release(&Wb);
    PyBuffer_Release(&Bb);
    PyBuffer_Release(&tb);
    PyBuffer_Release(&ob);
    return result;
}

PyObject *fglm_reduces(PyObject *self, PyObject *args); /* kernel/_fglm_proof.c */

static PyMethodDef methods[] = {
    {"fglm_step", fglm_step, METH_VARARGS, "One step of FGLM's linear algebra modulo p."},
    {"fglm_matrices", fglm_matrices, METH_VARARGS, "The multiplication matrices modulo p from a border plan."},
    {"fglm_replay", fglm_replay, METH_VARARGS, "A conversion's steps repeated at another prime."},
    {"fglm_walk", fglm_walk, METH_VARARGS, "A whole conversion modulo p: the visits and their steps."},
    {"fglm_plan", fglm_plan, METH_VARARGS, "The border's plan for fglm_matrices from a reduced basis."},
    {"fglm_reduces", fglm_reduces, METH_VARARGS, "Whether polynomials top-reduce to 0 (kernel/_fglm_proof.c)."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_fglm", "FGLM's linear algebra modulo p.", -1, methods};

PyMODINIT_FUNC PyInit__fglm(void)
{
    return PyModule_Create(&module);
}
