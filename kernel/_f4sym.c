/* F4's symbolic preprocessing and matrix layout, compiled (part of the optional extension
 * _f4rows; kernel/f4.py's F4._layout and F4._matrix_compiled do the same in Python).
 *
 * layout(nw, guard, dshift, ebits, maxdeg, mons, tdeg, coefs, active, specs, pivots)
 *   -> (pivcols, nonpivot, ids, off, col, val, rk, rstart, work), or None when a row's degree
 *   exceeds maxdeg
 *
 * Monomials are packed as in kernel/monomials.py, here as nw little-endian 64-bit words
 * (``int.to_bytes(8 nw, "little")``); guard holds the guard bits, the total degree is the
 * field of ebits bits at bit dshift.  mons[k] and coefs[k] (bytes): the terms of basis element
 * k, decreasing, and their coefficients (uint64); tdeg[k] its total degree; active[k]: whether
 * element k serves as a reducer: the reducer of a monomial is the first active element, by
 * increasing number of terms (then by index), whose leading monomial divides it; specs: the
 * pair rows (k, u) (u: packed cofactor, bytes or a Python int); pivots: a dict {L: (k, u)} of
 * the pair rows chosen as reducers of their leading monomial L (in its order).  Every
 * monomial of a row x^u * poly[k] that is not a pivot yet gets its reducer's row (which joins
 * the matrix), else it is a non-pivot column.
 * Returns the pivot columns and the non-pivot monomials (Python ints, increasing) and the rows
 * flat as kernel/f4_rows.Flat holds them (bytes: ids int32, the pivot ids 0..K-1 of the
 * reducers; off int64, col int32, val uint64: the reducers by pivot id without their leading
 * term, then the pair rows in the order given), per row its basis element rk and first term
 * rstart (int32: 1 for a reducer, 0 for a pair row); work: the number of terms of the
 * distinct rows.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* -- a hash table of fixed-length word keys, numbered in insertion order -------------------- */
typedef struct {
    int kw;
    uint64_t *keys;
    Py_ssize_t n, cap;
    int32_t *slot;
    size_t mask;
} Keys;

static uint64_t hash_words(const uint64_t *k, int kw)
{
    uint64_t h = 0x9E3779B97F4A7C15ULL;
    for (int i = 0; i < kw; i++) {
        h ^= k[i];
        h *= 0xff51afd7ed558ccdULL;
        h ^= h >> 32;
    }
    return h;
}

static int keys_init(Keys *t, int kw)
{
    t->kw = kw;
    t->n = 0;
    t->cap = 256;
    t->mask = 511;
    t->keys = malloc((size_t)t->cap * kw * sizeof(uint64_t));
    t->slot = malloc((t->mask + 1) * sizeof(int32_t));
    if (!t->keys || !t->slot)
        return -1;
    memset(t->slot, 0xff, (t->mask + 1) * sizeof(int32_t));
    return 0;
}

static void keys_free(Keys *t)
{
    free(t->keys);
    free(t->slot);
}

static const uint64_t *key_at(const Keys *t, Py_ssize_t i)
{
    return t->keys + (size_t)i * t->kw;
}

static int same_words(const uint64_t *a, const uint64_t *b, int kw)
{
    for (int i = 0; i < kw; i++)
        if (a[i] != b[i])
            return 0;
    return 1;
}

/* The number of key, inserted when absent (*fresh then 1); -1 when out of memory. */
static Py_ssize_t keys_put(Keys *t, const uint64_t *key, int *fresh)
{
    int kw = t->kw;
    size_t h = hash_words(key, kw) & t->mask;
    for (;;) {
        int32_t i = t->slot[h];
        if (i < 0)
            break;
        if (same_words(key_at(t, i), key, kw)) {
            *fresh = 0;
            return i;
        }
        h = (h + 1) & t->mask;
    }
    if (t->n == t->cap) {
        uint64_t *k = realloc(t->keys, (size_t)t->cap * 2 * kw * sizeof(uint64_t));
        if (!k)
            return -1;
        t->keys = k;
        t->cap *= 2;
    }
    memcpy(t->keys + (size_t)t->n * kw, key, (size_t)kw * sizeof(uint64_t));
    t->slot[h] = (int32_t)t->n;
    *fresh = 1;
    Py_ssize_t id = t->n++;
    if ((size_t)(2 * t->n) > t->mask) {  /* grow and rehash at half load */
        size_t size = 2 * (t->mask + 1);
        int32_t *s = malloc(size * sizeof(int32_t));
        if (!s)
            return -1;
        memset(s, 0xff, size * sizeof(int32_t));
        t->mask = size - 1;
        for (Py_ssize_t i = 0; i < t->n; i++) {
            size_t g = hash_words(key_at(t, i), kw) & t->mask;
            while (s[g] >= 0)
                g = (g + 1) & t->mask;
            s[g] = (int32_t)i;
        }
        free(t->slot);
        t->slot = s;
    }
    return id;
}

/* -- packed monomials as words ---------------------------------------------------------------- */
static void add_words(uint64_t *c, const uint64_t *a, const uint64_t *b, int nw)
{
    uint64_t carry = 0;
    for (int i = 0; i < nw; i++) {
        uint64_t s = a[i] + carry;
        uint64_t c1 = s < carry;
        c[i] = s + b[i];
        carry = c1 | (c[i] < s);
    }
}

static void sub_words(uint64_t *c, const uint64_t *a, const uint64_t *b, int nw)
{
    uint64_t borrow = 0;
    for (int i = 0; i < nw; i++) {
        uint64_t d = a[i] - b[i];
        uint64_t b1 = a[i] < b[i];
        c[i] = d - borrow;
        borrow = b1 | (d < borrow);
    }
}

/* Whether a divides x: ((x | G) - a) & G == G, no field borrowing from the next. */
static int divides(const uint64_t *a, const uint64_t *x, const uint64_t *G, int nw)
{
    uint64_t borrow = 0;
    for (int i = 0; i < nw; i++) {
        uint64_t v = x[i] | G[i];
        uint64_t d = v - a[i];
        uint64_t b1 = v < a[i];
        uint64_t e = d - borrow;
        borrow = b1 | (d < borrow);
        if ((e & G[i]) != G[i])
            return 0;
    }
    return 1;
}

static uint64_t field(const uint64_t *w, int shift, int width, int nw)
{
    int i = shift >> 6, o = shift & 63;
    uint64_t v = w[i] >> o;
    if (o && o + width > 64 && i + 1 < nw)
        v |= w[i + 1] << (64 - o);
    return v & ((1ULL << width) - 1);
}

static int cmp_nw;
static const uint64_t *cmp_base;

static int cmp_mono(const void *a, const void *b)
{
    const uint64_t *x = cmp_base + (size_t)*(const int32_t *)a * cmp_nw;
    const uint64_t *y = cmp_base + (size_t)*(const int32_t *)b * cmp_nw;
    for (int i = cmp_nw - 1; i >= 0; i--)
        if (x[i] != y[i])
            return x[i] < y[i] ? -1 : 1;
    return 0;
}

typedef struct {
    int nw;
    Py_ssize_t nbasis;
    const uint64_t **mons;
    const uint64_t **coefs;
    Py_ssize_t *len;
} Basis;

/* Grow an int32 array to hold n entries. */
static int reserve32(int32_t **a, Py_ssize_t *cap, Py_ssize_t n)
{
    if (n <= *cap)
        return 0;
    Py_ssize_t c = *cap ? *cap : 256;
    while (c < n)
        c *= 2;
    int32_t *b = realloc(*a, (size_t)c * sizeof(int32_t));
    if (!b)
        return -1;
    *a = b;
    *cap = c;
    return 0;
}

static int reserve64(int64_t **a, Py_ssize_t *cap, Py_ssize_t n)
{
    if (n <= *cap)
        return 0;
    Py_ssize_t c = *cap ? *cap : 256;
    while (c < n)
        c *= 2;
    int64_t *b = realloc(*a, (size_t)c * sizeof(int64_t));
    if (!b)
        return -1;
    *a = b;
    *cap = c;
    return 0;
}

/* A packed monomial given as bytes (nw little-endian words) or as a nonnegative integer (a Python
 * int, or another integer type such as python-flint's fmpz through __index__). */
static int parse_words(PyObject *o, uint64_t *dst, int nw)
{
    if (PyBytes_Check(o)) {
        if (PyBytes_GET_SIZE(o) != 8 * nw)
            return -1;
        memcpy(dst, PyBytes_AS_STRING(o), 8 * (size_t)nw);
        return 0;
    }
    PyObject *x = PyNumber_Index(o);
    if (x == NULL) {
        PyErr_Clear();
        return -1;
    }
    int bad;
    if (nw == 1) {
        unsigned long long v = PyLong_AsUnsignedLongLong(x);
        bad = v == (unsigned long long)-1 && PyErr_Occurred();
        dst[0] = v;
    } else {
#if PY_VERSION_HEX >= 0x030D0000
        Py_ssize_t need = PyLong_AsNativeBytes(x, dst, 8 * (Py_ssize_t)nw,
                                               Py_ASNATIVEBYTES_LITTLE_ENDIAN | Py_ASNATIVEBYTES_REJECT_NEGATIVE);
        bad = need < 0 || need > 8 * nw;
#else
        bad = _PyLong_AsByteArray((PyLongObject *)x, (unsigned char *)dst, 8 * (size_t)nw, 1, 0) != 0;
#endif
    }
    Py_DECREF(x);
    if (bad)
        PyErr_Clear();
    return bad ? -1 : 0;
}

static int parse_row(PyObject *lo, PyObject *o, const Basis *B, uint64_t *key, uint64_t *lead)
{
    /* (k, u), and the leading monomial L of a pair row chosen as reducer (lo, else NULL):
     * key = u words then k; lead = L */
    if (!PyTuple_Check(o) || PyTuple_GET_SIZE(o) != 2)
        return -1;
    int nw = B->nw;
    Py_ssize_t k = PyLong_AsSsize_t(PyTuple_GET_ITEM(o, 0));
    if (k < 0 || k >= B->nbasis || parse_words(PyTuple_GET_ITEM(o, 1), key, nw))
        return -1;
    key[nw] = (uint64_t)k;
    return lo != NULL && parse_words(lo, lead, nw) ? -1 : 0;
}

PyObject *f4_layout(PyObject *self, PyObject *args)
{
    int nw, dshift, ebits;
    long long maxdeg;
    Py_buffer guard;
    PyObject *mons_o, *tdeg_o, *coefs_o, *active_o, *specs_o, *pivots_o;
    if (!PyArg_ParseTuple(args, "iy*iiLO!O!O!O!O!O!", &nw, &guard, &dshift, &ebits, &maxdeg,
                          &PyList_Type, &mons_o, &PyList_Type, &tdeg_o, &PyList_Type, &coefs_o,
                          &PyList_Type, &active_o, &PyList_Type, &specs_o, &PyDict_Type, &pivots_o))
        return NULL;
    PyObject *result = NULL;
    Basis B = {nw, PyList_GET_SIZE(mons_o), NULL, NULL, NULL};
    Keys rows = {0}, mono = {0};
    int32_t *red = NULL, *midx = NULL, *crow = NULL, *order = NULL, *code = NULL, *col = NULL;
    int32_t *rowk = NULL, *rowstart = NULL;
    int64_t *rowoff = NULL, *off = NULL;
    long long *tdeg = NULL;
    uint64_t *val = NULL, *leads = NULL, *tmp = NULL;
    Py_ssize_t redcap = 0, midxcap = 0, rowoffcap = 0, nmidx = 0;
    Py_ssize_t nspec = PyList_GET_SIZE(specs_o);
    Py_ssize_t nred = 0;
    int32_t *rk = NULL;
    const uint64_t *G = guard.buf;

    if (nw < 1 || nw > 64 || guard.len != 8 * nw || ebits < 1 || ebits > 62 || dshift < 0 || dshift + ebits > 64 * nw
        || PyList_GET_SIZE(tdeg_o) != B.nbasis || PyList_GET_SIZE(coefs_o) != B.nbasis
        || PyList_GET_SIZE(active_o) != B.nbasis)
        goto bad;
    B.mons = malloc((size_t)(B.nbasis + 1) * sizeof(uint64_t *));
    B.coefs = malloc((size_t)(B.nbasis + 1) * sizeof(uint64_t *));
    B.len = malloc((size_t)(B.nbasis + 1) * sizeof(Py_ssize_t));
    tdeg = malloc((size_t)(B.nbasis + 1) * sizeof(long long));
    rk = malloc((size_t)(B.nbasis + 1) * sizeof(int32_t));
    leads = malloc((size_t)(B.nbasis + 1) * nw * sizeof(uint64_t));
    tmp = malloc(3 * ((size_t)nw + 1) * sizeof(uint64_t));
    crow = malloc((size_t)(nspec + 1) * sizeof(int32_t));
    if (!B.mons || !B.coefs || !B.len || !tdeg || !rk || !leads || !tmp || !crow || keys_init(&rows, nw + 1) || keys_init(&mono, nw))
        goto nomem;
    for (Py_ssize_t k = 0; k < B.nbasis; k++) {
        PyObject *m = PyList_GET_ITEM(mons_o, k), *c = PyList_GET_ITEM(coefs_o, k);
        if (!PyBytes_Check(m) || !PyBytes_Check(c) || PyBytes_GET_SIZE(m) != PyBytes_GET_SIZE(c) * nw
            || PyBytes_GET_SIZE(c) % 8)
            goto bad;
        B.mons[k] = (const uint64_t *)PyBytes_AS_STRING(m);
        B.coefs[k] = (const uint64_t *)PyBytes_AS_STRING(c);
        B.len[k] = PyBytes_GET_SIZE(c) / 8;
        tdeg[k] = PyLong_AsLongLong(PyList_GET_ITEM(tdeg_o, k));
        if (tdeg[k] == -1 && PyErr_Occurred())
            goto done;
    }
    for (Py_ssize_t k = 0; k < B.nbasis; k++) {  /* the reducers: active, by length, then index */
        int on = PyObject_IsTrue(PyList_GET_ITEM(active_o, k));
        if (on < 0)
            goto done;
        if (!on)
            continue;
        if (B.len[k] == 0)
            goto bad;
        Py_ssize_t i = nred++;
        while (i > 0 && B.len[rk[i - 1]] > B.len[k]) {
            rk[i] = rk[i - 1];
            i--;
        }
        rk[i] = (int32_t)k;
    }
    for (Py_ssize_t i = 0; i < nred; i++)
        memcpy(leads + (size_t)i * nw, B.mons[rk[i]], 8 * (size_t)nw);
    uint64_t *key = tmp, *x = tmp + nw + 1, *lead = tmp + 2 * (nw + 1);
    int fresh;
    /* the pair rows chosen as reducers, then the other pair rows */
    PyObject *lo, *spec;
    for (Py_ssize_t pos = 0; PyDict_Next(pivots_o, &pos, &lo, &spec);) {
        if (parse_row(lo, spec, &B, key, lead))
            goto bad;
        Py_ssize_t r = keys_put(&rows, key, &fresh);
        Py_ssize_t xi = keys_put(&mono, lead, &fresh);
        if (r < 0 || xi < 0 || reserve32(&red, &redcap, mono.n))
            goto nomem;
        red[xi] = (int32_t)r;
    }
    for (Py_ssize_t i = 0; i < nspec; i++) {
        if (parse_row(NULL, PyList_GET_ITEM(specs_o, i), &B, key, lead))
            goto bad;
        Py_ssize_t r = keys_put(&rows, key, &fresh);
        if (r < 0)
            goto nomem;
        crow[i] = (int32_t)r;
    }
    /* every row's monomials; new rows (reducers) join the end of the list */
    long long work = 0;
    Py_ssize_t rowoffn = 0;
    for (Py_ssize_t r = 0; r < rows.n; r++) {
        if ((r & 1023) == 1023 && PyErr_CheckSignals())
            goto done;
        const uint64_t *u = key_at(&rows, r);
        Py_ssize_t k = (Py_ssize_t)u[nw], n = B.len[k];
        if ((long long)field(u, dshift, ebits, nw) + tdeg[k] > maxdeg) {
            result = Py_None;
            Py_INCREF(result);
            goto done;
        }
        work += n;
        if (reserve64(&rowoff, &rowoffcap, r + 2) || reserve32(&midx, &midxcap, nmidx + n))
            goto nomem;
        rowoff[r] = nmidx;
        rowoffn = r + 1;
        for (Py_ssize_t t = 0; t < n; t++) {
            add_words(x, u, B.mons[k] + (size_t)t * nw, nw);
            Py_ssize_t xi = keys_put(&mono, x, &fresh);
            if (xi < 0 || reserve32(&red, &redcap, mono.n))
                goto nomem;
            midx[nmidx++] = (int32_t)xi;
            if (!fresh)
                continue;
            red[xi] = -1;
            for (Py_ssize_t i = 0; i < nred; i++) {
                const uint64_t *lm = leads + (size_t)i * nw;
                if (divides(lm, x, G, nw)) {
                    sub_words(key, x, lm, nw);
                    key[nw] = (uint64_t)rk[i];
                    Py_ssize_t rr = keys_put(&rows, key, &fresh);
                    if (rr < 0)
                        goto nomem;
                    red[xi] = (int32_t)rr;
                    break;
                }
            }
            u = key_at(&rows, r);  /* the row keys may have moved */
        }
    }
    if (reserve64(&rowoff, &rowoffcap, rowoffn + 1))
        goto nomem;
    rowoff[rowoffn] = nmidx;
    /* columns: pivots and non-pivots, each increasing */
    Py_ssize_t N = mono.n, K = 0, m = 0;
    order = malloc((size_t)(N + 1) * sizeof(int32_t));
    code = malloc((size_t)(N + 1) * sizeof(int32_t));
    if (!order || !code)
        goto nomem;
    for (Py_ssize_t i = 0; i < N; i++)
        order[i] = (int32_t)i;
    cmp_nw = nw;
    cmp_base = mono.keys;
    qsort(order, (size_t)N, sizeof(int32_t), cmp_mono);
    PyObject *pivcols = PyList_New(0), *nonpivot = PyList_New(0);
    result = Py_BuildValue("(NN)", pivcols, nonpivot);  /* owns the lists */
    if (!pivcols || !nonpivot || !result)
        goto done;
    int32_t *pivrow = malloc((size_t)(N + 1) * sizeof(int32_t));
    if (!pivrow)
        goto nomem;
    for (Py_ssize_t i = 0; i < N; i++) {
        Py_ssize_t xi = order[i];
        PyObject *v = nw == 1 ? PyLong_FromUnsignedLongLong(key_at(&mono, xi)[0])
                              : _PyLong_FromByteArray((const unsigned char *)key_at(&mono, xi), 8 * (size_t)nw, 1, 0);
        if (!v) {
            free(pivrow);
            goto fail;
        }
        int bad_append;
        if (red[xi] >= 0) {
            pivrow[K] = red[xi];
            code[xi] = (int32_t)K++;
            bad_append = PyList_Append(pivcols, v);
        } else {
            code[xi] = ~(int32_t)m++;
            bad_append = PyList_Append(nonpivot, v);
        }
        Py_DECREF(v);
        if (bad_append) {
            free(pivrow);
            goto fail;
        }
    }
    /* the flat rows: reducers by pivot id (leading term left out), then the pair rows */
    Py_ssize_t total = 0;
    for (Py_ssize_t j = 0; j < K; j++)
        total += rowoff[pivrow[j] + 1] - rowoff[pivrow[j]] - 1;
    for (Py_ssize_t i = 0; i < nspec; i++)
        total += rowoff[crow[i] + 1] - rowoff[crow[i]];
    off = malloc((size_t)(K + nspec + 1) * sizeof(int64_t));
    col = malloc((size_t)(total + 1) * sizeof(int32_t));
    val = malloc((size_t)(total + 1) * sizeof(uint64_t));
    rowk = malloc((size_t)(2 * (K + nspec) + 1) * sizeof(int32_t));  /* ids, then rk */
    rowstart = malloc((size_t)(K + nspec + 1) * sizeof(int32_t));
    if (!off || !col || !val || !rowk || !rowstart) {
        free(pivrow);
        goto nomem_result;
    }
    Py_ssize_t e = 0;
    off[0] = 0;
    for (Py_ssize_t q = 0; q < K + nspec; q++) {
        Py_ssize_t r = q < K ? pivrow[q] : crow[q - K], start = q < K ? 1 : 0;
        Py_ssize_t k = (Py_ssize_t)key_at(&rows, r)[nw];
        if (q < K)
            rowk[q] = (int32_t)q;
        rowk[K + q] = (int32_t)k;
        rowstart[q] = (int32_t)start;
        const int32_t *mi = midx + rowoff[r];
        Py_ssize_t n = rowoff[r + 1] - rowoff[r];
        for (Py_ssize_t t = start; t < n; t++) {
            col[e] = code[mi[t]];
            val[e++] = B.coefs[k][t];
        }
        off[q + 1] = e;
    }
    free(pivrow);
    PyObject *full = Py_BuildValue("(OOy#y#y#y#y#y#L)", PyTuple_GET_ITEM(result, 0), PyTuple_GET_ITEM(result, 1),
                                   (const char *)rowk, (Py_ssize_t)(K * sizeof(int32_t)),
                                   (const char *)off, (Py_ssize_t)((K + nspec + 1) * sizeof(int64_t)),
                                   (const char *)col, (Py_ssize_t)(e * sizeof(int32_t)),
                                   (const char *)val, (Py_ssize_t)(e * sizeof(uint64_t)),
                                   (const char *)(rowk + K), (Py_ssize_t)((K + nspec) * sizeof(int32_t)),
                                   (const char *)rowstart, (Py_ssize_t)((K + nspec) * sizeof(int32_t)), work);
    Py_DECREF(result);
    result = full;
    goto done;
bad:
    PyErr_SetString(PyExc_ValueError, "f4 layout: bad arguments");
    goto done;
nomem_result:
nomem:
    PyErr_NoMemory();
fail:
    Py_CLEAR(result);
done:
    PyBuffer_Release(&guard);
    free(rk);
    free(rowk);
    free(rowstart);
    free(B.mons);
    free(B.coefs);
    free(B.len);
    free(tdeg);
    free(leads);
    free(tmp);
    free(crow);
    free(red);
    free(midx);
    free(rowoff);
    free(order);
    free(code);
    free(off);
    free(col);
    free(val);
    keys_free(&rows);
    keys_free(&mono);
    return result;
}

/* words(monomials, nw) -> bytes: nonnegative Python ints (packed monomials below 2^(64 nw)) as
 * nw little-endian 64-bit words each, one after the other (``int.to_bytes(8 nw, "little")``
 * joined; kernel/f4_rows.Packed converts basis elements with it). */
PyObject *f4_words(PyObject *self, PyObject *args)
{
    PyObject *seq;
    int nw;
    if (!PyArg_ParseTuple(args, "Oi", &seq, &nw))
        return NULL;
    PyObject *fast = PySequence_Fast(seq, "words: a sequence of ints");
    if (fast == NULL)
        return NULL;
    if (nw < 1) {
        Py_DECREF(fast);
        PyErr_SetString(PyExc_ValueError, "words: nw must be positive");
        return NULL;
    }
    Py_ssize_t n = PySequence_Fast_GET_SIZE(fast), nb = 8 * (Py_ssize_t)nw;
    PyObject *out = PyBytes_FromStringAndSize(NULL, n * nb);
    if (out == NULL) {
        Py_DECREF(fast);
        return NULL;
    }
    unsigned char *buf = (unsigned char *)PyBytes_AS_STRING(out);
    for (Py_ssize_t i = 0; i < n; i++) {
        /* an int, or an integer of another type (python-flint's fmpz) through __index__ */
        PyObject *x = PyNumber_Index(PySequence_Fast_GET_ITEM(fast, i));
        int bad;
        if (x == NULL) {
            PyErr_Clear();
            PyErr_SetString(PyExc_TypeError, "words: a sequence of ints");
            bad = -1;
        } else {
#if PY_VERSION_HEX >= 0x030D0000
            Py_ssize_t need = PyLong_AsNativeBytes(x, buf + i * nb, nb,
                                                   Py_ASNATIVEBYTES_LITTLE_ENDIAN | Py_ASNATIVEBYTES_REJECT_NEGATIVE);
            bad = need < 0 ? -1 : need > nb ? 1 : 0;
#else
            bad = _PyLong_AsByteArray((PyLongObject *)x, buf + i * nb, (size_t)nb, 1, 0);
#endif
            Py_DECREF(x);
            if (bad > 0)
                PyErr_SetString(PyExc_OverflowError, "words: a monomial does not fit nw words");
        }
        if (bad) {
            Py_DECREF(fast);
            Py_DECREF(out);
            return NULL;
        }
    }
    Py_DECREF(fast);
    return out;
}

/* exponents(monomials, eshifts, ebits) -> {monomial: exponent tuple}: the exponents of packed
 * monomials (nonnegative integers) whose exponent fields lie in the lowest 64 bits (else
 * ValueError), each unpacked once: field f of ebits bits at bit eshifts[f] (kernel/monomials.py's
 * Packing.unpack_all does the same in Python). */
PyObject *f4_exponents(PyObject *self, PyObject *args)
{
    PyObject *seq, *shifts_o;
    int ebits;
    if (!PyArg_ParseTuple(args, "OO!i", &seq, &PyTuple_Type, &shifts_o, &ebits))
        return NULL;
    Py_ssize_t n = PyTuple_GET_SIZE(shifts_o);
    if (ebits < 1 || ebits > 62 || n > 64) {
        PyErr_SetString(PyExc_ValueError, "exponents: bad packing");
        return NULL;
    }
    int shift[64], top = 0;
    for (Py_ssize_t f = 0; f < n; f++) {
        long v = PyLong_AsLong(PyTuple_GET_ITEM(shifts_o, f));
        if (v < 0 || v > (1L << 20)) {
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_ValueError, "exponents: bad packing");
            return NULL;
        }
        shift[f] = (int)v;
        if (shift[f] + ebits > top)
            top = shift[f] + ebits;
    }
    if (top > 64) {
        PyErr_SetString(PyExc_ValueError, "exponents: the exponent fields exceed 64 bits");
        return NULL;
    }
    PyObject *fast = PySequence_Fast(seq, "exponents: a sequence of ints");
    if (fast == NULL)
        return NULL;
    PyObject *out = PyDict_New();
    if (out == NULL) {
        Py_DECREF(fast);
        return NULL;
    }
    for (Py_ssize_t i = 0; i < PySequence_Fast_GET_SIZE(fast); i++) {
        PyObject *m = PySequence_Fast_GET_ITEM(fast, i);
        int known = PyDict_Contains(out, m);
        if (known > 0)
            continue;
        PyObject *t = NULL, *x = known == 0 ? PyNumber_Index(m) : NULL;
        if (x != NULL) {
            uint64_t w = PyLong_AsUnsignedLongLongMask(x);  /* the lowest 64 bits */
            t = PyErr_Occurred() ? NULL : PyTuple_New(n);
            for (Py_ssize_t f = 0; t && f < n; f++) {
                PyObject *e = PyLong_FromUnsignedLongLong(field(&w, shift[f], ebits, 1));
                if (e == NULL)
                    Py_CLEAR(t);
                else
                    PyTuple_SET_ITEM(t, f, e);
            }
        } else if (known == 0) {
            PyErr_Clear();
            PyErr_SetString(PyExc_TypeError, "exponents: a sequence of nonnegative ints");
        }
        Py_XDECREF(x);
        if (t == NULL || PyDict_SetItem(out, m, t)) {
            Py_XDECREF(t);
            Py_DECREF(out);
            Py_DECREF(fast);
            return NULL;
        }
        Py_DECREF(t);
    }
    Py_DECREF(fast);
    return out;
}

/* pack(exponents, units) -> [packed monomial], or None when a unit or a monomial does not fit 128
 * bits: each exponent vector e (a sequence of nonnegative ints) as the sum of e_f units[f]
 * (kernel/monomials.py's Packing.pack, which computes the same in Python ints). */
PyObject *f4_pack(PyObject *self, PyObject *args)
{
    PyObject *seq, *units_o;
    if (!PyArg_ParseTuple(args, "OO!", &seq, &PyTuple_Type, &units_o))
        return NULL;
    Py_ssize_t n = PyTuple_GET_SIZE(units_o);
    if (n > 1024)
        Py_RETURN_NONE;
    unsigned __int128 units[1024];
    for (Py_ssize_t f = 0; f < n; f++) {
        PyObject *u = PyTuple_GET_ITEM(units_o, f);
        unsigned char b[16];
        if (!PyLong_Check(u) || _PyLong_AsByteArray((PyLongObject *)u, b, 16, 1, 0)) {
            PyErr_Clear();
            Py_RETURN_NONE;
        }
        unsigned __int128 v = 0;
        for (int i = 15; i >= 0; i--)
            v = (v << 8) | b[i];
        units[f] = v;
    }
    PyObject *fast = PySequence_Fast(seq, "pack: a sequence of exponent vectors");
    if (fast == NULL)
        return NULL;
    Py_ssize_t N = PySequence_Fast_GET_SIZE(fast);
    PyObject *out = PyList_New(N);
    for (Py_ssize_t i = 0; out && i < N; i++) {
        PyObject *e = PySequence_Fast(PySequence_Fast_GET_ITEM(fast, i), "pack: exponent vectors");
        if (e == NULL || PySequence_Fast_GET_SIZE(e) != n) {
            if (e != NULL)
                PyErr_SetString(PyExc_ValueError, "pack: an exponent vector of another length");
            Py_XDECREF(e);
            Py_CLEAR(out);
            break;
        }
        unsigned __int128 acc = 0, t;
        int over = 0;
        for (Py_ssize_t f = 0; f < n && !over; f++) {
            long x = PyLong_AsLong(PySequence_Fast_GET_ITEM(e, f));
            if (x == -1 && PyErr_Occurred()) {
                PyErr_Clear();
                over = 1;
            } else {
                over = x < 0 || __builtin_mul_overflow((unsigned __int128)x, units[f], &t)
                       || __builtin_add_overflow(acc, t, &acc);
            }
        }
        Py_DECREF(e);
        if (over) {  /* beyond 128 bits (or not a small nonnegative exponent): the caller packs in Python */
            Py_DECREF(out);
            Py_DECREF(fast);
            Py_RETURN_NONE;
        }
        PyObject *v;
        if ((acc >> 64) == 0) {
            v = PyLong_FromUnsignedLongLong((uint64_t)acc);
        } else {
            unsigned char bytes[16];
            for (int k = 0; k < 16; k++)
                bytes[k] = (unsigned char)(acc >> (8 * k));
            v = _PyLong_FromByteArray(bytes, 16, 1, 0);
        }
        if (v == NULL)
            Py_CLEAR(out);
        else
            PyList_SET_ITEM(out, i, v);
    }
    Py_DECREF(fast);
    return out;
}

/* term_dicts(rows, eshifts, ebits, scale) -> [{exponent tuple: coefficient}]: each row (packed
 * monomials, coefficients: two sequences of equal length) as a dict in the row's order, the
 * exponents cut from the packed monomials as exponents() does (fields within the lowest 64 bits,
 * else ValueError; the tuples of equal monomials shared), each coefficient multiplied by scale
 * unless scale is None (kernel/monomials.py's Packing.term_dicts). */
PyObject *f4_term_dicts(PyObject *self, PyObject *args)
{
    PyObject *rows, *shifts_o, *scale;
    int ebits;
    if (!PyArg_ParseTuple(args, "OO!iO", &rows, &PyTuple_Type, &shifts_o, &ebits, &scale))
        return NULL;
    Py_ssize_t n = PyTuple_GET_SIZE(shifts_o);
    int shift[64], top = 0;
    if (ebits < 1 || ebits > 62 || n > 64) {
        PyErr_SetString(PyExc_ValueError, "term_dicts: bad packing");
        return NULL;
    }
    for (Py_ssize_t f = 0; f < n; f++) {
        long v = PyLong_AsLong(PyTuple_GET_ITEM(shifts_o, f));
        if (v < 0 || v > 64) {
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_ValueError, "term_dicts: the exponent fields exceed 64 bits");
            return NULL;
        }
        shift[f] = (int)v;
        if (shift[f] + ebits > top)
            top = shift[f] + ebits;
    }
    if (top > 64) {
        PyErr_SetString(PyExc_ValueError, "term_dicts: the exponent fields exceed 64 bits");
        return NULL;
    }
    PyObject *fast = PySequence_Fast(rows, "term_dicts: a sequence of rows");
    if (fast == NULL)
        return NULL;
    PyObject *seen = PyDict_New(), *out = PyList_New(0);
    if (seen == NULL)
        Py_CLEAR(out);
    for (Py_ssize_t r = 0; out && r < PySequence_Fast_GET_SIZE(fast); r++) {
        PyObject *row = PySequence_Fast_GET_ITEM(fast, r);
        PyObject *ms = NULL, *cs = NULL, *d = NULL;
        if (!PyTuple_Check(row) || PyTuple_GET_SIZE(row) != 2
            || !(ms = PySequence_Fast(PyTuple_GET_ITEM(row, 0), "term_dicts: monomials"))
            || !(cs = PySequence_Fast(PyTuple_GET_ITEM(row, 1), "term_dicts: coefficients"))
            || PySequence_Fast_GET_SIZE(ms) != PySequence_Fast_GET_SIZE(cs) || !(d = PyDict_New())) {
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_ValueError, "term_dicts: rows of (monomials, coefficients)");
            Py_XDECREF(ms);
            Py_XDECREF(cs);
            Py_CLEAR(out);
            break;
        }
        int bad = PyList_Append(out, d) < 0;
        Py_DECREF(d);
        for (Py_ssize_t t = 0; !bad && t < PySequence_Fast_GET_SIZE(ms); t++) {
            PyObject *m = PySequence_Fast_GET_ITEM(ms, t), *c = PySequence_Fast_GET_ITEM(cs, t);
            PyObject *e = PyDict_GetItemWithError(seen, m);  /* borrowed */
            if (e != NULL) {
                Py_INCREF(e);
            } else if (!PyErr_Occurred()) {
                PyObject *x = PyNumber_Index(m);
                uint64_t w = x ? PyLong_AsUnsignedLongLongMask(x) : 0;  /* the lowest 64 bits */
                Py_XDECREF(x);
                e = x && !PyErr_Occurred() ? PyTuple_New(n) : NULL;
                for (Py_ssize_t f = 0; e && f < n; f++) {
                    PyObject *v = PyLong_FromUnsignedLongLong(field(&w, shift[f], ebits, 1));
                    if (v == NULL)
                        Py_CLEAR(e);
                    else
                        PyTuple_SET_ITEM(e, f, v);
                }
                if (e && PyDict_SetItem(seen, m, e))
                    Py_CLEAR(e);
            }
            PyObject *v = e == NULL ? NULL : scale == Py_None ? (Py_INCREF(c), c) : PyNumber_Multiply(scale, c);
            bad = v == NULL || PyDict_SetItem(d, e, v) < 0;
            Py_XDECREF(e);
            Py_XDECREF(v);
        }
        Py_DECREF(ms);
        Py_DECREF(cs);
        if (bad)
            Py_CLEAR(out);
    }
    Py_DECREF(fast);
    Py_XDECREF(seen);
    return out;
}
