/* The rational reconstruction of modular F4's lift over QQ, compiled for moduli below 2^62 (part
 * of the optional extension _f4rows; kernel/modular.py's Reconstructor does the same in Python
 * for any modulus and falls back to it).
 *
 * ratrec_rows(values, out, m, i, j, den) -> (i, j, den, height)
 *   values: lists of ints in [0, m) (the residues mod m of the basis's coefficients, row by
 *   row); out: lists of the same lengths, whose entries from row i, position j on are set to
 *   (n, d) with n/d = a mod m, |n|, d <= sqrt(m/2) -- exactly Reconstructor.attempt's loop: a
 *   running denominator den makes a coefficient one product when a den mod m (symmetric) is
 *   small, else Wang's reconstruction, and den becomes the lcm (or the new denominator once the
 *   lcm exceeds the bound).  Stops at the first coefficient with no reconstruction: returns
 *   where it stopped and height -1; else the end and the height in bits of the whole lift
 *   (of out: the largest bit length of |n| or d over the entries n/d in lowest terms, as
 *   python-flint's fmpq.height_bits).
 *
 * fractions(out, fmpq, cache) -> the rows of out as fractions fmpq(n) for d = 1, else fmpq(n, d)
 *   (fmpq: python-flint's type; Reconstructor's complete lift); those with |n|, d below 2^15 are
 *   taken from the dict cache by (n, d), where up to CACHED of them are kept for the next lifts.
 *
 * agree_rows(out, residues, p, i, j) -> (i, j) or None
 *   The first entry (n, d) of out, in rows 0..i (row i only below position j), with
 *   n != r d mod p or p | d (r its residue mod p), as Reconstructor.check; None if all agree.
 *   OverflowError when an entry does not fit 64 bits (the caller then checks in Python).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include "_intmath.h"
#include <stdint.h>

#define CACHED 65536  /* fractions kept in fractions()'s cache */

static uint64_t isqrt64(uint64_t x)
{
    uint64_t r = 0, bit = 1ULL << 62;
    while (bit > x)
        bit >>= 2;
    while (bit) {
        if (x >= r + bit) {
            x -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return r;
}

/* Wang's n/d = a mod m with |n|, d <= bound and gcd(n, d) = 1 (modular.ratrec); 0 when none */
static int ratrec64(int64_t a, int64_t m, int64_t bound, int64_t *n, int64_t *d)
{
    int64_t r0 = m, r1 = a % m, s0 = 0, s1 = 1;
    while (r1 > bound) {
        int64_t q = r0 / r1, t;
        t = r0 - q * r1;
        r0 = r1;
        r1 = t;
        t = s0 - q * s1;
        s0 = s1;
        s1 = t;
    }
    int64_t as1 = s1 < 0 ? -s1 : s1;
    if (s1 == 0 || as1 > bound || gcd_i64(r1, as1) != 1)
        return 0;
    *n = s1 > 0 ? r1 : -r1;
    *d = as1;
    return 1;
}

static int bit_length(uint64_t x)
{
    return x ? 64 - __builtin_clzll(x) : 0;
}

/* The height in bits of the entries (n, d) of out (all fit 64 bits: made by ratrec_rows). */
static int height(PyObject *out)
{
    int h = 0;
    for (Py_ssize_t i = 0; i < PyList_GET_SIZE(out); i++) {
        PyObject *row = PyList_GET_ITEM(out, i);
        for (Py_ssize_t j = 0; j < PyList_GET_SIZE(row); j++) {
            PyObject *t = PyList_GET_ITEM(row, j);
            long long n = PyLong_AsLongLong(PyTuple_GET_ITEM(t, 0)), d = PyLong_AsLongLong(PyTuple_GET_ITEM(t, 1));
            if (PyErr_Occurred())
                return -1;
            int64_t g = gcd_i64(n, d);
            uint64_t an = (uint64_t)(n < 0 ? -n : n) / (uint64_t)g, ad = (uint64_t)d / (uint64_t)g;
            int b = bit_length(an > ad ? an : ad);
            if (b > h)
                h = b;
        }
    }
    return h;
}

static PyObject *pair(int64_t n, int64_t d)
{
    PyObject *t = PyTuple_New(2);
    if (!t)
        return NULL;
    PyObject *a = PyLong_FromLongLong(n), *b = PyLong_FromLongLong(d);
    if (!a || !b) {
        Py_XDECREF(a);
        Py_XDECREF(b);
        Py_DECREF(t);
        return NULL;
    }
    PyTuple_SET_ITEM(t, 0, a);
    PyTuple_SET_ITEM(t, 1, b);
    return t;
}

PyObject *f4_ratrec_rows(PyObject *self, PyObject *args)
{
    PyObject *values, *out;
    long long m, den;
    Py_ssize_t i, j;
    if (!PyArg_ParseTuple(args, "O!O!LnnL", &PyList_Type, &values, &PyList_Type, &out, &m, &i, &j, &den))
        return NULL;
    if (m < 2 || m >= (1LL << 62) || den < 1 || PyList_GET_SIZE(out) != PyList_GET_SIZE(values)) {
        PyErr_SetString(PyExc_ValueError, "ratrec_rows: bad arguments");
        return NULL;
    }
    const int64_t half = m / 2, bound = (int64_t)isqrt64((uint64_t)half);
    const Py_ssize_t nrows = PyList_GET_SIZE(values);
    for (; i < nrows; i++, j = 0) {
        PyObject *cs = PyList_GET_ITEM(values, i), *row = PyList_GET_ITEM(out, i);
        if (!PyList_Check(cs) || !PyList_Check(row) || PyList_GET_SIZE(cs) != PyList_GET_SIZE(row)) {
            PyErr_SetString(PyExc_ValueError, "ratrec_rows: bad rows");
            return NULL;
        }
        for (; j < PyList_GET_SIZE(cs); j++) {
            long long a = PyLong_AsLongLong(PyList_GET_ITEM(cs, j));
            if (a == -1 && PyErr_Occurred())
                return NULL;
            if (a < 0 || a >= m) {
                PyErr_SetString(PyExc_ValueError, "ratrec_rows: a residue out of range");
                return NULL;
            }
            int64_t b = (int64_t)((u128)a * (u128)den % (u128)m), n, d;
            if (b > half)
                b -= m;
            if (-bound <= b && b <= bound && den <= bound) {
                n = b;
                d = den;
            } else {
                if (!ratrec64(a, m, bound, &n, &d))
                    return Py_BuildValue("(nnLi)", i, j, den, -1);
                int64_t l = den / gcd_i64(den, d) * d;  /* den, d <= bound < 2^31 */
                den = l > bound ? d : l;
            }
            PyObject *t = pair(n, d);
            if (!t)
                return NULL;
            PyList_SetItem(row, j, t);  /* steals t */
        }
    }
    int h = height(out);
    return h < 0 ? NULL : Py_BuildValue("(nnLi)", i, j, den, h);
}

PyObject *f4_agree_rows(PyObject *self, PyObject *args)
{
    PyObject *out, *residues;
    long long p;
    Py_ssize_t i0, j0;
    if (!PyArg_ParseTuple(args, "O!O!Lnn", &PyList_Type, &out, &PyList_Type, &residues, &p, &i0, &j0))
        return NULL;
    if (p < 2 || p >= (1LL << 62) || PyList_GET_SIZE(residues) < PyList_GET_SIZE(out)) {
        PyErr_SetString(PyExc_ValueError, "agree_rows: bad arguments");
        return NULL;
    }
    Py_ssize_t last = i0 + 1 < PyList_GET_SIZE(out) ? i0 + 1 : PyList_GET_SIZE(out);
    for (Py_ssize_t i = 0; i < last; i++) {
        PyObject *row = PyList_GET_ITEM(out, i), *rs = PyList_GET_ITEM(residues, i);
        if (!PyList_Check(row) || !PyList_Check(rs) || PyList_GET_SIZE(rs) < PyList_GET_SIZE(row)) {
            PyErr_SetString(PyExc_ValueError, "agree_rows: bad rows");
            return NULL;
        }
        Py_ssize_t stop = i == i0 ? j0 : PyList_GET_SIZE(row);
        for (Py_ssize_t j = 0; j < stop; j++) {
            PyObject *t = PyList_GET_ITEM(row, j);
            if (!PyTuple_Check(t) || PyTuple_GET_SIZE(t) != 2) {
                PyErr_SetString(PyExc_ValueError, "agree_rows: bad entry");
                return NULL;
            }
            long long n = PyLong_AsLongLong(PyTuple_GET_ITEM(t, 0));
            if (n == -1 && PyErr_Occurred())
                return NULL;
            long long d = PyLong_AsLongLong(PyTuple_GET_ITEM(t, 1));
            if (d == -1 && PyErr_Occurred())
                return NULL;
            long long r = PyLong_AsLongLong(PyList_GET_ITEM(rs, j));
            if (r == -1 && PyErr_Occurred())
                return NULL;
            i128 diff = ((i128)n - (i128)r * (i128)d) % (i128)p;
            if (diff != 0 || d % p == 0)
                return Py_BuildValue("(nn)", i, j);
        }
    }
    Py_RETURN_NONE;
}

PyObject *f4_fractions(PyObject *self, PyObject *args)
{
    PyObject *out, *fmpq, *cache;
    if (!PyArg_ParseTuple(args, "O!OO!", &PyList_Type, &out, &fmpq, &PyDict_Type, &cache))
        return NULL;
    Py_ssize_t nrows = PyList_GET_SIZE(out);
    PyObject *lift = PyList_New(nrows);
    for (Py_ssize_t i = 0; lift && i < nrows; i++) {
        PyObject *row = PyList_GET_ITEM(out, i);
        if (!PyList_Check(row)) {
            PyErr_SetString(PyExc_ValueError, "fractions: rows of (n, d)");
            Py_CLEAR(lift);
            break;
        }
        PyObject *got = PyList_New(PyList_GET_SIZE(row));
        PyList_SET_ITEM(lift, i, got);
        for (Py_ssize_t j = 0; got && j < PyList_GET_SIZE(row); j++) {
            PyObject *t = PyList_GET_ITEM(row, j), *q = NULL;
            if (!PyTuple_Check(t) || PyTuple_GET_SIZE(t) != 2) {
                PyErr_SetString(PyExc_ValueError, "fractions: rows of (n, d)");
            } else {
                PyObject *n = PyTuple_GET_ITEM(t, 0), *d = PyTuple_GET_ITEM(t, 1);
                int overflow_n, overflow_d;
                long long nv = PyLong_AsLongLongAndOverflow(n, &overflow_n);
                long long dv = PyLong_AsLongLongAndOverflow(d, &overflow_d);
                int small = !PyErr_Occurred() && !overflow_n && !overflow_d && nv > -32768 && nv < 32768
                            && dv > 0 && dv < 32768;
                if (small) {
                    q = PyDict_GetItemWithError(cache, t);  /* borrowed */
                    if (q != NULL)
                        Py_INCREF(q);
                }
                if (q == NULL && !PyErr_Occurred()) {
                    q = dv == 1 && !overflow_d ? PyObject_CallOneArg(fmpq, n) : PyObject_CallFunctionObjArgs(fmpq, n, d, NULL);
                    if (q && small && PyDict_GET_SIZE(cache) < CACHED && PyDict_SetItem(cache, t, q))
                        Py_CLEAR(q);
                }
            }
            if (q == NULL) {
                Py_CLEAR(lift);
                break;
            }
            PyList_SET_ITEM(got, j, q);
        }
        if (!got)
            Py_CLEAR(lift);
    }
    return lift;
}
