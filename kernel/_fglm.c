/* One step of FGLM's linear algebra modulo p < 2^31 (kernel/fglm.py ``fglm_modp``), part of the
 * optional extension mech.kernel._f4rows.
 *
 * The state lives in Python-owned arrays of uint32 (array('I')) and int32 (array('i')):
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
 * result is None.  Accumulation in 64 bits with a reduction every `lim` additions. */
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

PyObject *fglm_step(PyObject *self, PyObject *args)
{
    unsigned long long p_;
    Py_ssize_t D, K;
    int mode;
    Py_ssize_t a, b;
    Py_buffer M, nfs, piv, slot;
    if (!PyArg_ParseTuple(args, "Knnw*w*w*w*inn", &p_, &D, &K, &M, &nfs, &piv, &slot, &mode, &a, &b))
        return NULL;
    const uint64_t p = p_;
    const Py_ssize_t W = 2 * D + 1;
    uint32_t *Mv = M.buf, *N = nfs.buf, *R = piv.buf;
    int32_t *S = slot.buf;
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
    if (s0 < 0) {
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
        const uint64_t inv = inv_mod(x[s0], p);
        uint32_t *row = R + K * W;
        for (Py_ssize_t t = 0; t < W; t++)
            row[t] = (uint32_t)(x[t] * inv % p);
        S[K] = (int32_t)s0;
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
