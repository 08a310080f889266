/* The linear algebra of one F4 matrix modulo a prime p < 2^31, compiled (optional: the
 * pure-Python path of kernel/f4_vectors.py computes the same, see kernel/f4_rows.py).
 *
 * reduce(p, m, K, nred, ids, off, col, val, want, stop) -> (used, E, W)
 *
 * Rows are given flat: row r has the entries off[r] .. off[r+1]-1 with column codes col[]
 * (c >= 0: pivot column c, whose reducer is unit-leading; c < 0: non-pivot slot ~c) and
 * coefficients val[] (below p).  The first nred rows are reducers (leading entry left out),
 * filling the pivot ids ids[r] (0 <= id < K, increasing with the columns' monomials) in
 * increasing order, so every pivot a reducer refers to lies below its own and is filled
 * before.  Either each reducer becomes its reduced tail T = N - sum c_j T_j over its pivot
 * entries (dense in the slots; combine) and the pair rows are reduced the same way, or, when
 * that is expected to cost more (sequential_pays), each pair row is reduced by the reducer rows
 * one pivot at a time from the highest down (reduce_seq): the same reduced rows, the row minus
 * the unique combination of reducers clearing its pivot entries.  The reduced pair rows are
 * brought to reduced echelon form exactly as kernel/f4_vectors.echelon does (same operations
 * in the same order).
 * Returns used = [(pair row index, pivot slot)], E = [(pivot slot, slots, values)] by
 * increasing pivot slot (slots highest first), W = [(slots, values)] of the reduced tails
 * of the pivot ids in want.  With stop set, returns as soon as a pair row does not reduce
 * to zero (used then holds that row).  An optional last argument forces the dense tails (0) or
 * the pivot-by-pivot reduction (1) (tests; -1, the default: the cheaper by estimate).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    uint32_t **rows;
    int32_t *len;
    Py_ssize_t K;
} Table;

/* x mod p by Barrett's method with pinv = floor((2^64 - 1) / p): the quotient estimate is at most
 * two below the true one (the same result as x % p, without a hardware division). */
static inline uint64_t mod_p(uint64_t x, uint64_t p, uint64_t pinv)
{
    uint64_t r = x - (uint64_t)(((unsigned __int128)x * pinv) >> 64) * p;
    if (r >= p)
        r -= p;
    if (r >= p)
        r -= p;
    return r;
}

static void table_free(Table *t)
{
    if (t->rows) {
        for (Py_ssize_t j = 0; j < t->K; j++)
            free(t->rows[j]);
        free(t->rows);
    }
    free(t->len);
}

static void normalize(uint64_t *acc, Py_ssize_t b, uint64_t p, uint64_t pinv)
{
    for (Py_ssize_t s = 0; s < b; s++)
        acc[s] = mod_p(acc[s], p, pinv);
}

/* acc[0..m) := the reduced row r (entries < p); returns the bound (highest nonzero + 1),
 * -1 on a bad pivot reference. */
static Py_ssize_t combine(const Table *T, uint64_t *acc, Py_ssize_t m, uint64_t p, uint64_t pinv, uint64_t hmax,
                          const int64_t *off, const int32_t *col, const uint64_t *val, Py_ssize_t r)
{
    Py_ssize_t b = 0;
    for (int64_t e = off[r]; e < off[r + 1]; e++) {
        int32_t c = col[e];
        Py_ssize_t need;
        if (c < 0)
            need = (Py_ssize_t)(~c) + 1;
        else {
            if (c >= T->K || T->len[c] < 0)
                return -1;
            need = T->len[c];
        }
        if (need > b)
            b = need;
    }
    if (b > m)
        return -1;
    memset(acc, 0, (size_t)b * sizeof(uint64_t));
    uint64_t count = 0;
    for (int64_t e = off[r]; e < off[r + 1]; e++) {
        int32_t c = col[e];
        uint64_t v = mod_p(val[e], p, pinv);
        if (c < 0) {
            acc[~c] += v;
            continue;
        }
        if (v == 0)
            continue;
        uint64_t nv = p - v;
        const uint32_t *t = T->rows[c];
        Py_ssize_t n = T->len[c];
        for (Py_ssize_t s = 0; s < n; s++)
            acc[s] += nv * t[s];
        if (++count >= hmax) {
            normalize(acc, b, p, pinv);
            count = 0;
        }
    }
    normalize(acc, b, p, pinv);
    while (b > 0 && acc[b - 1] == 0)
        b--;
    return b;
}

/* Row r reduced by the reducer rows one pivot at a time, from the highest pivot down (the
 * rows' tails as given, not reduced first): accP[0..K) and acc[0..m) take the pivot and the
 * non-pivot entries; pivot j with a nonzero entry c subtracts c times reducer row rowof[j], whose
 * pivot entries all lie below j and whose values are below p (both checked by the caller).  Leaves the reduced row (non-pivot slots, entries < p) in
 * acc[0..b) and returns b (highest nonzero + 1), -1 on a bad pivot reference.  The same numbers
 * as combine(): a row minus the unique combination of reducers clearing its pivot entries.
 * Entries stay below p^2 (p^2 + p^2 < 2^63 for p < 2^31) by one conditional subtraction. */
static Py_ssize_t reduce_seq(const int64_t *rowof, Py_ssize_t K, uint64_t *accP, uint64_t *acc, Py_ssize_t m,
                             uint64_t p, uint64_t pinv, const int64_t *off, const int32_t *col,
                             const uint64_t *val, Py_ssize_t r, int32_t below)
{
    uint64_t p2 = p * p;
    Py_ssize_t top = below < 0 ? K : below;  /* pivots a reducer row may refer to lie below its own */
    memset(accP, 0, (size_t)top * sizeof(uint64_t));
    memset(acc, 0, (size_t)m * sizeof(uint64_t));
    for (int64_t e = off[r]; e < off[r + 1]; e++) {
        int32_t c = col[e];
        uint64_t v = mod_p(val[e], p, pinv);
        if (c < 0) {
            if ((Py_ssize_t)(~c) >= m)
                return -1;
            acc[~c] += v;
        } else {
            if (c >= top || rowof[c] < 0)
                return -1;
            accP[c] += v;
        }
    }
    for (Py_ssize_t j = top - 1; j >= 0; j--) {
        uint64_t c = mod_p(accP[j], p, pinv);
        if (!c)
            continue;
        uint64_t f = p - c;
        int64_t rj = rowof[j];
        for (int64_t e = off[rj]; e < off[rj + 1]; e++) {  /* (references checked by the caller) */
            int32_t cc = col[e];
            uint64_t *x = cc < 0 ? acc + ~cc : accP + cc;
            uint64_t y = *x + f * val[e];
            *x = y >= p2 ? y - p2 : y;
        }
    }
    Py_ssize_t b = m;
    normalize(acc, m, p, pinv);
    while (b > 0 && acc[b - 1] == 0)
        b--;
    return b;
}

static PyObject *support(const uint64_t *x, Py_ssize_t b)
{
    PyObject *slots = PyList_New(0), *vals = PyList_New(0);
    if (!slots || !vals)
        goto fail;
    for (Py_ssize_t s = b - 1; s >= 0; s--) {
        if (x[s]) {
            PyObject *a = PyLong_FromSsize_t(s), *v = PyLong_FromUnsignedLongLong(x[s]);
            if (!a || !v || PyList_Append(slots, a) || PyList_Append(vals, v)) {
                Py_XDECREF(a);
                Py_XDECREF(v);
                goto fail;
            }
            Py_DECREF(a);
            Py_DECREF(v);
        }
    }
    return Py_BuildValue("(NN)", slots, vals);
fail:
    Py_XDECREF(slots);
    Py_XDECREF(vals);
    return NULL;
}

static uint64_t inverse(uint64_t a, uint64_t p)
{
    int64_t t = 0, nt = 1, r = (int64_t)p, nr = (int64_t)a;
    while (nr) {
        int64_t q = r / nr, tmp;
        tmp = t - q * nt; t = nt; nt = tmp;
        tmp = r - q * nr; r = nr; nr = tmp;
    }
    return (uint64_t)(t < 0 ? t + (int64_t)p : t);
}

/* Whether reducing the pair rows (and wanted tails) one pivot at a time (reduce_seq) is
 * expected to cost less than reducing every reducer to a dense tail first (combine): at most,
 * a row meets each reducer's entries once, against each pivot entry of the matrix meeting a
 * dense tail of about m/2 slots (a quarter more for large primes, whose sums are normalized
 * more often).  Measured on the matrices of benchmarks/cases.py (RESULTS.md, session 13). */
static int sequential_pays(uint64_t p, Py_ssize_t m, Py_ssize_t nred, Py_ssize_t R, Py_ssize_t nwant,
                           const int64_t *off, const int32_t *col)
{
    double piv = 0;
    for (int64_t e = 0; e < off[R]; e++)
        if (col[e] >= 0)
            piv += 1;
    double dense = piv * (double)m / 2 * (p >= (1u << 20) ? 1.25 : 1.0);
    return (double)(R - nred + nwant) * (double)off[nred] < dense;
}

static PyObject *f4_reduce(PyObject *self, PyObject *args)
{
    unsigned long long p_;
    Py_ssize_t m, K, nred;
    int stop, mode = -1;
    Py_buffer ids, off, col, val, want;
    if (!PyArg_ParseTuple(args, "Knnny*y*y*y*y*p|i", &p_, &m, &K, &nred, &ids, &off, &col, &val, &want, &stop,
                          &mode))
        return NULL;
    uint64_t p = p_, pinv = p_ >= 2 ? UINT64_MAX / p_ : 0;
    PyObject *result = NULL, *used = NULL, *E = NULL, *W = NULL;
    Table T = {NULL, NULL, K};
    uint64_t *acc = NULL, **piv = NULL, *accP = NULL, *vmod = NULL;
    int64_t *rowof = NULL;
    Py_ssize_t *pslot = NULL, npiv = 0;
    Py_ssize_t R = off.len / (Py_ssize_t)sizeof(int64_t) - 1;
    const int32_t *pid = ids.buf, *pcol = col.buf, *pwant = want.buf;
    const int64_t *poff = off.buf;
    const uint64_t *pval = val.buf;
    Py_ssize_t nwant = want.len / (Py_ssize_t)sizeof(int32_t);

    if (p < 2 || p >= (1ULL << 31) || R < nred || ids.len / (Py_ssize_t)sizeof(int32_t) < nred) {
        PyErr_SetString(PyExc_ValueError, "f4 rows: bad arguments");
        goto done;
    }
    uint64_t hmax = (UINT64_MAX - p) / ((p - 1) * (p - 1));
    if (hmax > (1ULL << 30))
        hmax = 1ULL << 30;
    T.rows = calloc((size_t)(K ? K : 1), sizeof(uint32_t *));
    T.len = malloc((size_t)(K ? K : 1) * sizeof(int32_t));
    acc = malloc((size_t)(m ? m : 1) * sizeof(uint64_t));
    piv = calloc((size_t)(R - nred + 1), sizeof(uint64_t *));
    pslot = malloc((size_t)(R - nred + 1) * sizeof(Py_ssize_t));
    used = PyList_New(0);
    E = PyList_New(0);
    W = PyList_New(0);
    if (!T.rows || !T.len || !acc || !piv || !pslot || !used || !E || !W) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t j = 0; j < K; j++)
        T.len[j] = -1;
    int seq = mode == 1 || (mode < 0 && sequential_pays(p, m, nred, R, nwant, poff, pcol));
    if (seq) {
        Py_ssize_t nent = (Py_ssize_t)poff[R];
        rowof = malloc((size_t)(K ? K : 1) * sizeof(int64_t));
        accP = malloc((size_t)(K ? K : 1) * sizeof(uint64_t));
        vmod = malloc((size_t)(nent ? nent : 1) * sizeof(uint64_t));
        if (!rowof || !accP || !vmod) {
            PyErr_NoMemory();
            goto done;
        }
        for (Py_ssize_t j = 0; j < K; j++)
            rowof[j] = -1;
        for (Py_ssize_t r = 0; r < nred; r++) {
            if (pid[r] < 0 || pid[r] >= K) {
                PyErr_SetString(PyExc_ValueError, "f4 rows: bad pivot reference");
                goto done;
            }
            rowof[pid[r]] = r;
        }
        for (Py_ssize_t r = 0; r < nred; r++)  /* every reducer refers to filled pivots below its own */
            for (int64_t e = poff[r]; e < poff[r + 1]; e++) {
                int32_t c = pcol[e];
                if (c >= 0 ? c >= pid[r] || rowof[c] < 0 : (Py_ssize_t)(~c) >= m) {
                    PyErr_SetString(PyExc_ValueError, "f4 rows: bad pivot reference");
                    goto done;
                }
            }
        for (Py_ssize_t e = 0; e < nent; e++)
            vmod[e] = mod_p(pval[e], p, pinv);
        pval = vmod;
    }
    for (Py_ssize_t r = 0; r < nred && !seq; r++) {
        if ((r & 1023) == 1023 && PyErr_CheckSignals())
            goto done;  /* Ctrl-C, a time limit's signal: the handler's exception propagates */
        Py_ssize_t b = combine(&T, acc, m, p, pinv, hmax, poff, pcol, pval, r);
        int32_t j = pid[r];
        if (b < 0 || j < 0 || j >= K) {
            PyErr_SetString(PyExc_ValueError, "f4 rows: bad pivot reference");
            goto done;
        }
        uint32_t *t = malloc((size_t)(b ? b : 1) * sizeof(uint32_t));
        if (!t) {
            PyErr_NoMemory();
            goto done;
        }
        for (Py_ssize_t s = 0; s < b; s++)
            t[s] = (uint32_t)acc[s];
        free(T.rows[j]);
        T.rows[j] = t;
        T.len[j] = (int32_t)b;
    }
    /* pair rows: reduce, then forward elimination by the earlier pivot rows in turn */
    for (Py_ssize_t r = nred; r < R; r++) {
        if (((r - nred) & 255) == 255 && PyErr_CheckSignals())
            goto done;
        Py_ssize_t b = seq ? reduce_seq(rowof, K, accP, acc, m, p, pinv, poff, pcol, pval, r, -1)
                           : combine(&T, acc, m, p, pinv, hmax, poff, pcol, pval, r);
        if (b < 0) {
            PyErr_SetString(PyExc_ValueError, "f4 rows: bad pivot reference");
            goto done;
        }
        if (b == 0)
            continue;
        memset(acc + b, 0, (size_t)(m - b) * sizeof(uint64_t));
        uint64_t n = 0;
        for (Py_ssize_t i = 0; i < npiv; i++) {
            uint64_t c = mod_p(acc[pslot[i]], p, pinv);
            if (c) {
                uint64_t f = p - c, *y = piv[i];
                for (Py_ssize_t s = 0; s <= pslot[i]; s++)
                    acc[s] += f * y[s];
                if (++n >= hmax) {
                    normalize(acc, m, p, pinv);
                    n = 0;
                }
            }
        }
        normalize(acc, m, p, pinv);
        Py_ssize_t s0 = m - 1;
        while (s0 >= 0 && acc[s0] == 0)
            s0--;
        if (s0 < 0)
            continue;
        if (acc[s0] != 1) {
            uint64_t inv = inverse(acc[s0], p);
            for (Py_ssize_t s = 0; s <= s0; s++)
                acc[s] = mod_p(acc[s] * inv, p, pinv);
        }
        PyObject *u = Py_BuildValue("(nn)", r - nred, s0);
        if (!u || PyList_Append(used, u)) {
            Py_XDECREF(u);
            goto done;
        }
        Py_DECREF(u);
        if (stop)
            break;
        uint64_t *y = malloc((size_t)m * sizeof(uint64_t));
        if (!y) {
            PyErr_NoMemory();
            goto done;
        }
        memcpy(y, acc, (size_t)m * sizeof(uint64_t));
        piv[npiv] = y;
        pslot[npiv++] = s0;
    }
    /* back substitution from the last pivot row */
    if (!stop) {
        for (Py_ssize_t i = npiv - 2; i >= 0; i--) {
            uint64_t *x = piv[i], n = 0;
            for (Py_ssize_t k = i + 1; k < npiv; k++) {
                uint64_t c = mod_p(x[pslot[k]], p, pinv);
                if (c) {
                    uint64_t f = p - c, *y = piv[k];
                    for (Py_ssize_t s = 0; s <= pslot[k]; s++)
                        x[s] += f * y[s];
                    if (++n >= hmax) {
                        normalize(x, pslot[i] + 1, p, pinv);
                        n = 0;
                    }
                }
            }
            normalize(x, pslot[i] + 1, p, pinv);
        }
        /* E by increasing pivot slot */
        Py_ssize_t *order = malloc((size_t)(npiv ? npiv : 1) * sizeof(Py_ssize_t));
        if (!order) {
            PyErr_NoMemory();
            goto done;
        }
        for (Py_ssize_t i = 0; i < npiv; i++) {
            Py_ssize_t k = i;
            while (k > 0 && pslot[order[k - 1]] > pslot[i]) {
                order[k] = order[k - 1];
                k--;
            }
            order[k] = i;
        }
        for (Py_ssize_t i = 0; i < npiv; i++) {
            Py_ssize_t k = order[i];
            PyObject *sv = support(piv[k], pslot[k] + 1), *e;
            if (!sv) {
                free(order);
                goto done;
            }
            e = Py_BuildValue("(nNN)", pslot[k], PyTuple_GET_ITEM(sv, 0), PyTuple_GET_ITEM(sv, 1));
            Py_INCREF(PyTuple_GET_ITEM(sv, 0));
            Py_INCREF(PyTuple_GET_ITEM(sv, 1));
            Py_DECREF(sv);
            if (!e || PyList_Append(E, e)) {
                Py_XDECREF(e);
                free(order);
                goto done;
            }
            Py_DECREF(e);
        }
        free(order);
    }
    for (Py_ssize_t i = 0; i < nwant; i++) {
        int32_t j = pwant[i];
        if (j < 0 || j >= K || (seq ? rowof[j] < 0 : T.len[j] < 0)) {
            PyErr_SetString(PyExc_ValueError, "f4 rows: unknown pivot wanted");
            goto done;
        }
        Py_ssize_t b = T.len[j];
        if (seq) {
            b = reduce_seq(rowof, K, accP, acc, m, p, pinv, poff, pcol, pval, rowof[j], j);
            if (b < 0) {
                PyErr_SetString(PyExc_ValueError, "f4 rows: bad pivot reference");
                goto done;
            }
        } else {
            for (Py_ssize_t s = 0; s < b; s++)
                acc[s] = T.rows[j][s];
        }
        PyObject *sv = support(acc, b);
        if (!sv || PyList_Append(W, sv)) {
            Py_XDECREF(sv);
            goto done;
        }
        Py_DECREF(sv);
    }
    result = Py_BuildValue("(OOO)", used, E, W);
done:
    Py_XDECREF(used);
    Py_XDECREF(E);
    Py_XDECREF(W);
    table_free(&T);
    if (piv) {
        for (Py_ssize_t i = 0; i < npiv; i++)
            free(piv[i]);
        free(piv);
    }
    free(pslot);
    free(acc);
    free(accP);
    free(vmod);
    free(rowof);
    PyBuffer_Release(&ids);
    PyBuffer_Release(&off);
    PyBuffer_Release(&col);
    PyBuffer_Release(&val);
    PyBuffer_Release(&want);
    return result;
}

/* gather(coefs, rk, rstart, off) -> val: the coefficients of the recorded rows of a matrix
 * for another prime, flat (uint64 bytes): row r is coefs[rk[r]][rstart[r]:], whose length
 * must be off[r+1] - off[r] (kernel/f4_rows.Plan). */
static PyObject *f4_gather(PyObject *self, PyObject *args)
{
    PyObject *coefs, *out = NULL;
    Py_buffer rk, rstart, off;
    if (!PyArg_ParseTuple(args, "O!y*y*y*", &PyList_Type, &coefs, &rk, &rstart, &off))
        return NULL;
    Py_ssize_t R = rk.len / (Py_ssize_t)sizeof(int32_t);
    const int32_t *pk = rk.buf, *ps = rstart.buf;
    const int64_t *po = off.buf;
    if (rstart.len != rk.len || off.len != (R + 1) * (Py_ssize_t)sizeof(int64_t) || po[0] != 0) {
        PyErr_SetString(PyExc_ValueError, "f4 gather: bad arguments");
        goto done;
    }
    out = PyBytes_FromStringAndSize(NULL, (Py_ssize_t)(po[R] * (int64_t)sizeof(uint64_t)));
    if (!out)
        goto done;
    uint64_t *val = (uint64_t *)PyBytes_AS_STRING(out);
    for (Py_ssize_t r = 0; r < R; r++) {
        PyObject *cs = pk[r] >= 0 && pk[r] < PyList_GET_SIZE(coefs) ? PyList_GET_ITEM(coefs, pk[r]) : NULL;
        if (!cs || !PyList_Check(cs) || ps[r] < 0 || PyList_GET_SIZE(cs) - ps[r] != po[r + 1] - po[r]) {
            PyErr_SetString(PyExc_ValueError, "f4 gather: a row does not fit its polynomial");
            Py_CLEAR(out);
            goto done;
        }
        for (Py_ssize_t t = ps[r]; t < PyList_GET_SIZE(cs); t++) {
            uint64_t v = PyLong_AsUnsignedLongLong(PyList_GET_ITEM(cs, t));
            if (v == (uint64_t)-1 && PyErr_Occurred()) {
                Py_CLEAR(out);
                goto done;
            }
            *val++ = v;
        }
    }
done:
    PyBuffer_Release(&rk);
    PyBuffer_Release(&rstart);
    PyBuffer_Release(&off);
    return out;
}

/* subplan(off, col, rk, rstart, K, rows, roots) -> (ids, off, col, rk, rstart): from the plan of
 * a whole matrix (reducer j is row j for the pivots 0..K-1, then the pair rows; kernel/f4_rows.Plan's
 * arrays), the plan of the pair rows `rows` (int32, numbered from 0 after the reducers) and of the
 * reducers they and the pivots `roots` need, transitively: the needed pivot ids increasing, their
 * rows, then the pair rows in the order given (all arrays as bytes, as Plan holds them). */
static PyObject *f4_subplan(PyObject *self, PyObject *args)
{
    Py_buffer off, col, rk, rstart, rows, roots;
    Py_ssize_t K;
    if (!PyArg_ParseTuple(args, "y*y*y*y*ny*y*", &off, &col, &rk, &rstart, &K, &rows, &roots))
        return NULL;
    PyObject *result = NULL;
    const int64_t *po = off.buf;
    const int32_t *pc = col.buf, *pk = rk.buf, *ps = rstart.buf, *pr = rows.buf, *pt = roots.buf;
    Py_ssize_t R = off.len / (Py_ssize_t)sizeof(int64_t) - 1;
    Py_ssize_t nrows = rows.len / (Py_ssize_t)sizeof(int32_t), nroots = roots.len / (Py_ssize_t)sizeof(int32_t);
    char *need = NULL;
    int32_t *stack = NULL, *ids = NULL, *ocol = NULL, *ork = NULL, *ors = NULL;
    int64_t *ooff = NULL;
    if (K < 0 || K > R || col.len / (Py_ssize_t)sizeof(int32_t) < po[R] || rk.len / 4 < R || rstart.len / 4 < R) {
        PyErr_SetString(PyExc_ValueError, "f4 subplan: bad arguments");
        goto done;
    }
    need = calloc((size_t)(K ? K : 1), 1);
    stack = malloc((size_t)(K + 1) * sizeof(int32_t));
    if (!need || !stack) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t top = 0, total = 0;
    for (Py_ssize_t i = 0; i < nroots + nrows; i++) {  /* the roots, then the pair rows' pivots */
        Py_ssize_t q = i < nroots ? -1 : K + pr[i - nroots];
        if (q >= R || (q < 0 && (pt[i] < 0 || pt[i] >= K)) || (q >= 0 && q < K)) {
            PyErr_SetString(PyExc_ValueError, "f4 subplan: bad row");
            goto done;
        }
        if (q < 0) {
            if (!need[pt[i]]) {
                need[pt[i]] = 1;
                stack[top++] = pt[i];
            }
            continue;
        }
        total += po[q + 1] - po[q];
        for (int64_t e = po[q]; e < po[q + 1]; e++)
            if (pc[e] >= 0 && pc[e] < K && !need[pc[e]]) {
                need[pc[e]] = 1;
                stack[top++] = pc[e];
            }
    }
    while (top > 0) {
        int32_t j = stack[--top];
        for (int64_t e = po[j]; e < po[j + 1]; e++)
            if (pc[e] >= 0 && pc[e] < K && !need[pc[e]]) {
                need[pc[e]] = 1;
                stack[top++] = pc[e];
            }
    }
    Py_ssize_t nids = 0;
    for (Py_ssize_t j = 0; j < K; j++)
        if (need[j]) {
            nids++;
            total += po[j + 1] - po[j];
        }
    Py_ssize_t n = nids + nrows;
    ids = malloc((size_t)(nids + 1) * sizeof(int32_t));
    ooff = malloc((size_t)(n + 1) * sizeof(int64_t));
    ocol = malloc((size_t)(total + 1) * sizeof(int32_t));
    ork = malloc((size_t)(n + 1) * sizeof(int32_t));
    ors = malloc((size_t)(n + 1) * sizeof(int32_t));
    if (!ids || !ooff || !ocol || !ork || !ors) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t a = 0, w = 0;
    ooff[0] = 0;
    for (Py_ssize_t i = 0, j = 0; i < n; i++) {
        Py_ssize_t q;
        if (i < nids) {
            while (!need[j])
                j++;
            ids[i] = (int32_t)j;
            q = j++;
        } else {
            q = K + pr[i - nids];
        }
        for (int64_t e = po[q]; e < po[q + 1]; e++)
            ocol[w++] = pc[e];
        ooff[++a] = w;
        ork[i] = pk[q];
        ors[i] = ps[q];
    }
    result = Py_BuildValue("(y#y#y#y#y#)", (const char *)ids, (Py_ssize_t)(nids * 4), (const char *)ooff,
                           (Py_ssize_t)((n + 1) * 8), (const char *)ocol, (Py_ssize_t)(w * 4),
                           (const char *)ork, (Py_ssize_t)(n * 4), (const char *)ors, (Py_ssize_t)(n * 4));
done:
    free(need);
    free(stack);
    free(ids);
    free(ooff);
    free(ocol);
    free(ork);
    free(ors);
    PyBuffer_Release(&off);
    PyBuffer_Release(&col);
    PyBuffer_Release(&rk);
    PyBuffer_Release(&rstart);
    PyBuffer_Release(&rows);
    PyBuffer_Release(&roots);
    return result;
}

PyObject *f4_layout(PyObject *self, PyObject *args);  /* kernel/_f4sym.c */
PyObject *f4_words(PyObject *self, PyObject *args);  /* kernel/_f4sym.c */
PyObject *f4_exponents(PyObject *self, PyObject *args);  /* kernel/_f4sym.c */
PyObject *f4_pack(PyObject *self, PyObject *args);  /* kernel/_f4sym.c */
PyObject *f4_term_dicts(PyObject *self, PyObject *args);  /* kernel/_f4sym.c */
PyObject *f4_ratrec_rows(PyObject *self, PyObject *args);  /* kernel/_f4lift.c */
PyObject *f4_agree_rows(PyObject *self, PyObject *args);  /* kernel/_f4lift.c */
PyObject *f4_fractions(PyObject *self, PyObject *args);  /* kernel/_f4lift.c */
extern PyTypeObject PairsType;  /* kernel/_f4pairs.c */

static PyMethodDef methods[] = {
    {"reduce", f4_reduce, METH_VARARGS, "Reduce one F4 matrix modulo p (see the module source)."},
    {"gather", f4_gather, METH_VARARGS, "The coefficients of recorded rows for another prime (see the source)."},
    {"subplan", f4_subplan, METH_VARARGS, "The plan of some pair rows and the reducers they need (see the source)."},
    {"layout", f4_layout, METH_VARARGS, "F4's symbolic preprocessing and matrix layout (see kernel/_f4sym.c)."},
    {"words", f4_words, METH_VARARGS, "Packed monomials as little-endian 64-bit words (see kernel/_f4sym.c)."},
    {"exponents", f4_exponents, METH_VARARGS, "The exponents of packed monomials (see kernel/_f4sym.c)."},
    {"pack", f4_pack, METH_VARARGS, "Exponent vectors as packed monomials (see kernel/_f4sym.c)."},
    {"term_dicts", f4_term_dicts, METH_VARARGS, "Packed rows as {exponents: coefficient} dicts (see kernel/_f4sym.c)."},
    {"ratrec_rows", f4_ratrec_rows, METH_VARARGS, "Rational reconstruction of a lift's rows (see kernel/_f4lift.c)."},
    {"agree_rows", f4_agree_rows, METH_VARARGS, "A lift's rows against residues modulo p (see kernel/_f4lift.c)."},
    {"fractions", f4_fractions, METH_VARARGS, "A lift's rows as python-flint fractions (see kernel/_f4lift.c)."},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_f4rows", "F4 row reduction modulo p.", -1, methods};

PyMODINIT_FUNC PyInit__f4rows(void)
{
    if (PyType_Ready(&PairsType) < 0)
        return NULL;
    PyObject *m = PyModule_Create(&module);
    if (m == NULL)
        return NULL;
    Py_INCREF(&PairsType);
    if (PyModule_AddObject(m, "Pairs", (PyObject *)&PairsType) < 0) {
        Py_DECREF(&PairsType);
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
