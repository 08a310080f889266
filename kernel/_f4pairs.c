/* F4's critical pairs and their Gebauer–Möller update, compiled (part of the optional extension
 * _f4rows; kernel/f4_pairs.py's PairSet does the same in Python, step for step, and documents
 * the interface).
 *
 * Pairs(nvars, ebits, units, w0, by_weight, maxdeg)
 *   units: the packed form of each variable (Python ints, kernel/monomials.py's Packing.units);
 *   w0: the first row of the ordering's weight matrix; by_weight: a pair's key is the weighted
 *   degree of its lcm (else its sugar); maxdeg: the packing's degree bound.
 * Each element keeps the exponents of its leading monomial (read from the packed integer's
 * exponent fields: variable f at bit (nvars - 1 - f) ebits) and its sugar; each pair its key,
 * the exponents of its lcm and (i, j), j = -1 for an input row.  The lcm's packed integer is
 * built when the pair is taken: the sum of e_f times units[f].
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    PyObject_HEAD
    int n, ebits, by_weight;
    int64_t maxdeg;
    PyObject *units;       /* tuple of Python ints */
    unsigned __int128 *units128;  /* the same as 128-bit words, when every unit fits one (else NULL) */
    int64_t *w0;           /* n */
    int32_t *ex;           /* element exponents, n per element */
    int64_t *sugar, *deg;  /* per element */
    Py_ssize_t ne, cape;
    int32_t *pex;          /* pair lcm exponents, n per pair */
    int64_t *key;
    int32_t *pi, *pj;
    Py_ssize_t np, capp;
    int32_t *cand;         /* scratch for the update: candidate exponents, n per candidate */
    int32_t *cidx;
    char *ccop;
    Py_ssize_t capc;
} Pairs;

/* Pair q moved to slot w (w <= q) when the set is compacted. */
static void pairs_move(Pairs *s, Py_ssize_t w, Py_ssize_t q)
{
    if (w == q)
        return;
    memmove(s->pex + w * s->n, s->pex + q * s->n, s->n * sizeof(int32_t));
    s->key[w] = s->key[q];
    s->pi[w] = s->pi[q];
    s->pj[w] = s->pj[q];
}

static int grow(void **a, Py_ssize_t n, size_t size)
{
    void *b = realloc(*a, (size_t)(n ? n : 1) * size);
    if (b == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    *a = b;
    return 0;
}

static int reserve_pairs(Pairs *s, Py_ssize_t need)
{
    if (need <= s->capp)
        return 0;
    Py_ssize_t cap = s->capp ? s->capp : 64;
    while (cap < need)
        cap *= 2;
    if (grow((void **)&s->pex, cap * s->n, sizeof(int32_t)) || grow((void **)&s->key, cap, sizeof(int64_t))
        || grow((void **)&s->pi, cap, sizeof(int32_t)) || grow((void **)&s->pj, cap, sizeof(int32_t)))
        return -1;
    s->capp = cap;
    return 0;
}

static void Pairs_dealloc(Pairs *s)
{
    Py_XDECREF(s->units);
    free(s->units128);
    free(s->w0); free(s->ex); free(s->sugar); free(s->deg);
    free(s->pex); free(s->key); free(s->pi); free(s->pj);
    free(s->cand); free(s->cidx); free(s->ccop);
    Py_TYPE(s)->tp_free((PyObject *)s);
}

static int Pairs_init(Pairs *s, PyObject *args, PyObject *kw)
{
    PyObject *units, *w0;
    int n, ebits, by_weight;
    long long maxdeg;
    if (!PyArg_ParseTuple(args, "iiO!O!pL", &n, &ebits, &PyTuple_Type, &units, &PyTuple_Type, &w0,
                          &by_weight, &maxdeg))
        return -1;
    if (n < 1 || ebits < 2 || ebits > 31 || PyTuple_GET_SIZE(units) != n || PyTuple_GET_SIZE(w0) != n) {
        PyErr_SetString(PyExc_ValueError, "Pairs: bad packing");
        return -1;
    }
    s->n = n;
    s->ebits = ebits;
    s->by_weight = by_weight;
    s->maxdeg = maxdeg;
    Py_INCREF(units);
    Py_XSETREF(s->units, units);
    free(s->units128);
    s->units128 = malloc((size_t)n * sizeof(unsigned __int128));
    if (s->units128 == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    for (int f = 0; f < n; f++) {
        PyObject *u = PyTuple_GET_ITEM(units, f);
        unsigned char b[16];
        if (!PyLong_Check(u) || _PyLong_AsByteArray((PyLongObject *)u, b, 16, 1, 0)) {
            PyErr_Clear();
            free(s->units128);
            s->units128 = NULL;
            break;
        }
        unsigned __int128 v = 0;
        for (int i = 15; i >= 0; i--)
            v = (v << 8) | b[i];
        s->units128[f] = v;
    }
    if (grow((void **)&s->w0, n, sizeof(int64_t)))
        return -1;
    for (int f = 0; f < n; f++) {
        s->w0[f] = PyLong_AsLongLong(PyTuple_GET_ITEM(w0, f));
        if (s->w0[f] == -1 && PyErr_Occurred())
            return -1;
    }
    return 0;
}

/* add(lead, sugar): a new element (its index is the number added before). */
static PyObject *Pairs_add(Pairs *s, PyObject *args)
{
    PyObject *lead;
    long long sugar;
    if (!PyArg_ParseTuple(args, "O!L", &PyLong_Type, &lead, &sugar))
        return NULL;
    int n = s->n;
    if (s->ne == s->cape) {
        Py_ssize_t cap = s->cape ? 2 * s->cape : 64;
        if (grow((void **)&s->ex, cap * n, sizeof(int32_t)) || grow((void **)&s->sugar, cap, sizeof(int64_t))
            || grow((void **)&s->deg, cap, sizeof(int64_t)))
            return NULL;
        s->cape = cap;
    }
    int32_t *e = s->ex + s->ne * n;
    int64_t d = 0;
    unsigned long long mask = (1ULL << s->ebits) - 1;
    PyObject *x = lead;
    Py_INCREF(x);
    for (int f = n - 1; f >= 0; f--) {  /* the last variable's field is the lowest */
        unsigned long long low = PyLong_AsUnsignedLongLongMask(x);
        if (low == (unsigned long long)-1 && PyErr_Occurred()) {
            Py_DECREF(x);
            return NULL;
        }
        e[f] = (int32_t)(low & mask);
        d += e[f];
        if (f) {
            PyObject *sh = PyLong_FromLong(s->ebits);
            PyObject *y = sh ? PyNumber_Rshift(x, sh) : NULL;
            Py_XDECREF(sh);
            Py_DECREF(x);
            if (y == NULL)
                return NULL;
            x = y;
        }
    }
    Py_DECREF(x);
    s->sugar[s->ne] = sugar;
    s->deg[s->ne] = d;
    s->ne++;
    Py_RETURN_NONE;
}

/* push(key, k): the pair of input row k (its lcm: its leading monomial). */
static PyObject *Pairs_push(Pairs *s, PyObject *args)
{
    long long key;
    int k;
    if (!PyArg_ParseTuple(args, "Li", &key, &k))
        return NULL;
    if (k < 0 || k >= s->ne) {
        PyErr_SetString(PyExc_IndexError, "Pairs.push: no such element");
        return NULL;
    }
    if (reserve_pairs(s, s->np + 1))
        return NULL;
    memcpy(s->pex + s->np * s->n, s->ex + (Py_ssize_t)k * s->n, s->n * sizeof(int32_t));
    s->key[s->np] = key;
    s->pi[s->np] = k;
    s->pj[s->np] = -1;
    s->np++;
    Py_RETURN_NONE;
}

static int divides(const int32_t *a, const int32_t *b, int n)
{
    for (int f = 0; f < n; f++)
        if (a[f] > b[f])
            return 0;
    return 1;
}

static int lex_cmp(const int32_t *a, const int32_t *b, int n)
{
    for (int f = 0; f < n; f++)
        if (a[f] != b[f])
            return a[f] < b[f] ? -1 : 1;
    return 0;
}

/* whether lcm(a, b) equals c */
static int lcm_is(const int32_t *a, const int32_t *b, const int32_t *c, int n)
{
    for (int f = 0; f < n; f++)
        if ((a[f] > b[f] ? a[f] : b[f]) != c[f])
            return 0;
    return 1;
}

static int sort_n;
static const int32_t *sort_cand;
static const int32_t *sort_idx;

static int cmp_cand(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    int c = lex_cmp(sort_cand + (Py_ssize_t)a * sort_n, sort_cand + (Py_ssize_t)b * sort_n, sort_n);
    if (c)
        return c;
    return sort_idx[a] < sort_idx[b] ? -1 : sort_idx[a] > sort_idx[b];
}

/* update(h, active): add element h (Gebauer–Möller, as PairSet.update); active: the Python
 * list of flags, updated in place.  False (nothing changed) when an lcm exceeds maxdeg. */
static PyObject *Pairs_update(Pairs *s, PyObject *args)
{
    int h;
    PyObject *active;
    if (!PyArg_ParseTuple(args, "iO!", &h, &PyList_Type, &active))
        return NULL;
    int n = s->n;
    if (h < 0 || h >= s->ne || PyList_GET_SIZE(active) <= h) {
        PyErr_SetString(PyExc_IndexError, "Pairs.update: no such element");
        return NULL;
    }
    if (s->capc < h + 1) {
        Py_ssize_t cap = h + 64;
        if (grow((void **)&s->cand, cap * n, sizeof(int32_t)) || grow((void **)&s->cidx, cap, sizeof(int32_t))
            || grow((void **)&s->ccop, cap, 1))
            return NULL;
        s->capc = cap;
    }
    const int32_t *H = s->ex + (Py_ssize_t)h * n;
    int nc = 0;
    for (int i = 0; i < h; i++) {
        if (PyObject_IsTrue(PyList_GET_ITEM(active, i)) != 1)
            continue;
        const int32_t *E = s->ex + (Py_ssize_t)i * n;
        int32_t *L = s->cand + (Py_ssize_t)nc * n;
        char coprime = 1;
        for (int f = 0; f < n; f++) {
            L[f] = E[f] > H[f] ? E[f] : H[f];
            if (E[f] && H[f])
                coprime = 0;
        }
        s->cidx[nc] = i;
        s->ccop[nc] = coprime;
        nc++;
    }
    int *order = malloc((size_t)(nc ? nc : 1) * sizeof(int));
    int *kept = malloc((size_t)(nc ? nc : 1) * sizeof(int));
    if (order == NULL || kept == NULL) {
        free(order);
        free(kept);
        return PyErr_NoMemory();
    }
    for (int c = 0; c < nc; c++)
        order[c] = c;
    sort_n = n;
    sort_cand = s->cand;
    sort_idx = s->cidx;
    qsort(order, nc, sizeof(int), cmp_cand);
    /* criteria M and F: in increasing order of the lcms (divisors first) */
    int nk = 0;
    for (int t = 0; t < nc; t++) {
        int c = order[t];
        const int32_t *L = s->cand + (Py_ssize_t)c * n;
        if (nk && lex_cmp(s->cand + (Py_ssize_t)kept[nk - 1] * n, L, n) == 0) {
            if (s->ccop[c] && !s->ccop[kept[nk - 1]])
                kept[nk - 1] = c;
            continue;
        }
        int skip = 0;
        for (int u = 0; u < nk && !skip; u++)
            skip = divides(s->cand + (Py_ssize_t)kept[u] * n, L, n);
        if (!skip)
            kept[nk++] = c;
    }
    /* the new pairs' keys (and the degree bound) before anything changes */
    int64_t *keys = malloc((size_t)(nk ? nk : 1) * sizeof(int64_t));
    if (keys == NULL) {
        free(order);
        free(kept);
        return PyErr_NoMemory();
    }
    int nnew = 0;
    for (int u = 0; u < nk; u++) {
        int c = kept[u];
        if (s->ccop[c])
            continue;
        const int32_t *L = s->cand + (Py_ssize_t)c * n;
        int i = s->cidx[c];
        int64_t dL = 0, w = 0;
        for (int f = 0; f < n; f++) {
            dL += L[f];
            w += s->w0[f] * L[f];
        }
        if (dL > s->maxdeg) {
            free(order);
            free(kept);
            free(keys);
            Py_RETURN_FALSE;
        }
        if (s->by_weight) {
            keys[u] = w;
        } else {
            int64_t a = s->sugar[i] + dL - s->deg[i], b = s->sugar[h] + dL - s->deg[h];
            keys[u] = a > b ? a : b;
        }
        nnew++;
    }
    /* criterion B on the old pairs */
    Py_ssize_t w = 0;
    for (Py_ssize_t q = 0; q < s->np; q++) {
        const int32_t *L = s->pex + q * n;
        int j = s->pj[q];
        if (j >= 0 && divides(H, L, n) && !lcm_is(s->ex + (Py_ssize_t)s->pi[q] * n, H, L, n)
            && !lcm_is(s->ex + (Py_ssize_t)j * n, H, L, n))
            continue;
        if (w != q) {
            memcpy(s->pex + w * n, L, n * sizeof(int32_t));
            s->key[w] = s->key[q];
            s->pi[w] = s->pi[q];
            s->pj[w] = j;
        }
        w++;
    }
    s->np = w;
    if (reserve_pairs(s, s->np + nnew)) {
        free(order);
        free(kept);
        free(keys);
        return NULL;
    }
    for (int u = 0; u < nk; u++) {
        int c = kept[u];
        if (s->ccop[c])
            continue;
        memcpy(s->pex + s->np * n, s->cand + (Py_ssize_t)c * n, n * sizeof(int32_t));
        s->key[s->np] = keys[u];
        s->pi[s->np] = s->cidx[c];
        s->pj[s->np] = h;
        s->np++;
    }
    free(order);
    free(kept);
    free(keys);
    for (int i = 0; i < h; i++) {
        if (PyObject_IsTrue(PyList_GET_ITEM(active, i)) == 1 && divides(H, s->ex + (Py_ssize_t)i * n, n)) {
            Py_INCREF(Py_False);
            PyList_SetItem(active, i, Py_False);
        }
    }
    Py_INCREF(Py_True);
    PyList_SetItem(active, h, Py_True);
    Py_RETURN_TRUE;
}

/* the packed monomial of exponents e - b (b NULL: of e): the sum of its e_f units[f], in 128-bit
 * words when they hold it, else in Python ints */
static PyObject *packed(Pairs *s, const int32_t *e, const int32_t *b)
{
    if (s->units128 != NULL) {
        unsigned __int128 acc = 0;
        int over = 0;
        for (int f = 0; f < s->n && !over; f++) {
            unsigned __int128 x = (uint64_t)(b ? e[f] - b[f] : e[f]), t;
            over = __builtin_mul_overflow(x, s->units128[f], &t) || __builtin_add_overflow(acc, t, &acc);
        }
        if (!over) {
            if ((acc >> 64) == 0)
                return PyLong_FromUnsignedLongLong((uint64_t)acc);
            unsigned char bytes[16];
            for (int i = 0; i < 16; i++)
                bytes[i] = (unsigned char)(acc >> (8 * i));
            return _PyLong_FromByteArray(bytes, 16, 1, 0);
        }
    }
    PyObject *acc = PyLong_FromLong(0);
    for (int f = 0; f < s->n && acc; f++) {
        long x = b ? e[f] - b[f] : e[f];
        if (!x)
            continue;
        PyObject *ex = PyLong_FromLong(x);
        PyObject *t = ex ? PyNumber_Multiply(ex, PyTuple_GET_ITEM(s->units, f)) : NULL;
        Py_XDECREF(ex);
        PyObject *r = t ? PyNumber_Add(acc, t) : NULL;
        Py_XDECREF(t);
        Py_DECREF(acc);
        acc = r;
    }
    return acc;
}

static PyObject *packed_lcm(Pairs *s, Py_ssize_t q)
{
    return packed(s, s->pex + q * s->n, NULL);
}

static PyObject *pair_tuple(Pairs *s, Py_ssize_t q)
{
    PyObject *L = packed_lcm(s, q);
    if (L == NULL)
        return NULL;
    return Py_BuildValue("(LNii)", (long long)s->key[q], L, s->pi[q], s->pj[q]);
}

/* take(): the pairs of the lowest key, removed, in their order, as (key, lcm, i, j) */
static PyObject *Pairs_take(Pairs *s, PyObject *unused)
{
    PyObject *out = PyList_New(0);
    if (out == NULL || s->np == 0)
        return out;
    int64_t d = s->key[0];
    for (Py_ssize_t q = 1; q < s->np; q++)
        if (s->key[q] < d)
            d = s->key[q];
    Py_ssize_t w = 0;
    for (Py_ssize_t q = 0; q < s->np; q++) {
        if (s->key[q] == d) {
            PyObject *t = pair_tuple(s, q);
            if (t == NULL || PyList_Append(out, t)) {
                Py_XDECREF(t);
                Py_DECREF(out);
                return NULL;
            }
            Py_DECREF(t);
            continue;
        }
        pairs_move(s, w++, q);
    }
    s->np = w;
    return out;
}

/* take_rows(): the pairs of the lowest key d, removed, as F4's rows: (d, pivots, rows) as
 * kernel/f4_pairs.pair_rows makes them from take() and the elements' leading monomials */
static PyObject *Pairs_take_rows(Pairs *s, PyObject *unused)
{
    if (s->np == 0) {
        PyErr_SetString(PyExc_IndexError, "Pairs.take_rows: no pairs");
        return NULL;
    }
    int64_t d = s->key[0];
    for (Py_ssize_t q = 1; q < s->np; q++)
        if (s->key[q] < d)
            d = s->key[q];
    PyObject *pivots = PyDict_New(), *rows = PyList_New(0), *seen = PySet_New(NULL), *result = NULL;
    if (!pivots || !rows || !seen)
        goto done;
    Py_ssize_t w = 0;
    for (Py_ssize_t q = 0; q < s->np; q++) {
        if (s->key[q] != d) {
            pairs_move(s, w++, q);
            continue;
        }
        const int32_t *L = s->pex + q * s->n;
        int32_t ks[2] = {s->pi[q], s->pj[q]};
        PyObject *Lo = NULL;
        for (int t = 0; t < (ks[1] < 0 ? 1 : 2); t++) {
            PyObject *u = packed(s, L, s->ex + (Py_ssize_t)ks[t] * s->n);
            PyObject *spec = u ? Py_BuildValue("(iN)", ks[t], u) : NULL;
            int known = spec ? PySet_Contains(seen, spec) : -1;
            int bad = known < 0 || (!known && PySet_Add(seen, spec));
            if (!bad && !known) {
                int is_pivot = 0;
                if (ks[1] >= 0) {
                    if (Lo == NULL)
                        Lo = packed(s, L, NULL);
                    int has = Lo ? PyDict_Contains(pivots, Lo) : -1;
                    is_pivot = has < 0 ? -1 : !has;
                }
                bad = is_pivot < 0 || (is_pivot ? PyDict_SetItem(pivots, Lo, spec) : PyList_Append(rows, spec));
            }
            Py_XDECREF(spec);
            if (bad) {
                Py_XDECREF(Lo);
                goto done;
            }
        }
        Py_XDECREF(Lo);
    }
    s->np = w;
    result = Py_BuildValue("(LOO)", (long long)d, pivots, rows);
done:
    Py_XDECREF(pivots);
    Py_XDECREF(rows);
    Py_XDECREF(seen);
    return result;
}

/* minimal(active): the active elements whose leading monomial no other active element's divides
 * (of equal ones, the first), by increasing index (kernel/f4_pairs.PairSet.minimal) */
static PyObject *Pairs_minimal(Pairs *s, PyObject *active)
{
    if (!PyList_Check(active) || PyList_GET_SIZE(active) > s->ne) {
        PyErr_SetString(PyExc_ValueError, "Pairs.minimal: a list of flags, one per element");
        return NULL;
    }
    Py_ssize_t ne = PyList_GET_SIZE(active);
    int n = s->n;
    char *on = malloc((size_t)ne + 1);
    PyObject *out = on ? PyList_New(0) : PyErr_NoMemory();
    if (out == NULL) {
        free(on);
        return NULL;
    }
    for (Py_ssize_t k = 0; k < ne; k++) {
        int t = PyObject_IsTrue(PyList_GET_ITEM(active, k));
        if (t < 0) {
            free(on);
            Py_DECREF(out);
            return NULL;
        }
        on[k] = (char)t;
    }
    for (Py_ssize_t k = 0; k < ne; k++) {
        if (!on[k])
            continue;
        const int32_t *e = s->ex + k * n;
        int minimal = 1;
        for (Py_ssize_t j = 0; j < ne && minimal; j++) {
            if (j == k || !on[j] || !divides(s->ex + j * n, e, n))
                continue;
            minimal = j < k ? 0 : memcmp(s->ex + j * n, e, n * sizeof(int32_t)) == 0;  /* a later equal one: k stays */
        }
        if (!minimal)
            continue;
        PyObject *v = PyLong_FromSsize_t(k);
        if (v == NULL || PyList_Append(out, v)) {
            Py_XDECREF(v);
            free(on);
            Py_DECREF(out);
            return NULL;
        }
        Py_DECREF(v);
    }
    free(on);
    return out;
}

/* lowest(): the lowest key (None without pairs) */
static PyObject *Pairs_lowest(Pairs *s, PyObject *unused)
{
    if (s->np == 0)
        Py_RETURN_NONE;
    int64_t d = s->key[0];
    for (Py_ssize_t q = 1; q < s->np; q++)
        if (s->key[q] < d)
            d = s->key[q];
    return PyLong_FromLongLong(d);
}

/* drop(d): forget the pairs of key d */
static PyObject *Pairs_drop(Pairs *s, PyObject *arg)
{
    long long d = PyLong_AsLongLong(arg);
    if (d == -1 && PyErr_Occurred())
        return NULL;
    Py_ssize_t w = 0;
    for (Py_ssize_t q = 0; q < s->np; q++) {
        if (s->key[q] == d)
            continue;
        pairs_move(s, w++, q);
    }
    s->np = w;
    Py_RETURN_NONE;
}

/* clear(): forget every pair */
static PyObject *Pairs_clear(Pairs *s, PyObject *unused)
{
    s->np = 0;
    Py_RETURN_NONE;
}

/* everything(): all pairs, in their order, as (key, lcm, i, j) */
static PyObject *Pairs_everything(Pairs *s, PyObject *unused)
{
    PyObject *out = PyList_New(s->np);
    for (Py_ssize_t q = 0; out && q < s->np; q++) {
        PyObject *t = pair_tuple(s, q);
        if (t == NULL) {
            Py_DECREF(out);
            return NULL;
        }
        PyList_SET_ITEM(out, q, t);
    }
    return out;
}

static Py_ssize_t Pairs_len(Pairs *s)
{
    return s->np;
}

static PyMethodDef Pairs_methods[] = {
    {"add", (PyCFunction)Pairs_add, METH_VARARGS, "add(lead, sugar): a new element."},
    {"push", (PyCFunction)Pairs_push, METH_VARARGS, "push(key, k): the pair of input row k."},
    {"update", (PyCFunction)Pairs_update, METH_VARARGS, "update(h, active): Gebauer–Möller; False on overflow."},
    {"take", (PyCFunction)Pairs_take, METH_NOARGS, "take(): the pairs of the lowest key, removed."},
    {"take_rows", (PyCFunction)Pairs_take_rows, METH_NOARGS, "take_rows(): those pairs as F4's rows."},
    {"minimal", (PyCFunction)Pairs_minimal, METH_O, "minimal(active): the minimal active elements."},
    {"lowest", (PyCFunction)Pairs_lowest, METH_NOARGS, "lowest(): the lowest key, or None."},
    {"drop", (PyCFunction)Pairs_drop, METH_O, "drop(d): forget the pairs of key d."},
    {"clear", (PyCFunction)Pairs_clear, METH_NOARGS, "clear(): forget every pair."},
    {"everything", (PyCFunction)Pairs_everything, METH_NOARGS, "everything(): all pairs."},
    {NULL, NULL, 0, NULL}
};

static PySequenceMethods Pairs_seq = {.sq_length = (lenfunc)Pairs_len};

PyTypeObject PairsType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "_f4rows.Pairs",
    .tp_basicsize = sizeof(Pairs),
    .tp_dealloc = (destructor)Pairs_dealloc,
    .tp_as_sequence = &Pairs_seq,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "F4's critical pairs with the Gebauer–Möller update (see kernel/_f4pairs.c).",
    .tp_methods = Pairs_methods,
    .tp_init = (initproc)Pairs_init,
    .tp_new = PyType_GenericNew,
};
