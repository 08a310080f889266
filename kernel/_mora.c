/* Mora's normal form for the ordering ds over Z/p (p < 2^31), compiled: the reduction loop of
 * kernel/mora.py's _mora (its inner function `reduce`) and the S-polynomial, step for step the
 * same as the Python code, so that the bases are the same.  Driven by kernel/mora_compiled.py;
 * the polynomials and the geobucket are in kernel/_mora_poly.h.
 *
 * A monomial of n variables is W = ceil((n + 1) / 4) words of 64 bits holding 16-bit fields,
 * most significant first: the total degree, then the exponents of x_n, ..., x_1 (the layout
 * of kernel/mora_packed.py's integers cut into words).  For ds a monomial is larger exactly
 * when its words are smaller (compared from the first), and multiplication adds word by word
 * (each field keeps a guard bit: exponents stay below 2^15).  A polynomial is an array of
 * terms, each W monomial words and one coefficient word, the leading term first; as Python
 * values they are `bytes` of that array.
 *
 * The pool of reducers (basis elements and intermediate polynomials, sorted by sugar) and the
 * polynomials postponed by the loop (a heap, as they would wait in the Python queue) live in a
 * capsule: pool_new, pool_insert, pool_truncate; `run` reduces a polynomial and then the
 * postponed ones that come before the queue's head, until one is irreducible and nonzero, the
 * queue's head comes first, or the step budget is spent.  Under a cut (K[x]/m^(cut+1), finite-
 * dimensional) reductions take the first reducer without the ecart rule (reduce_cut).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "_mora_poly.h"

static const char *POOL = "mech.mora.pool";

static void pool_free(PyObject *cap)
{
    Pool *P = PyCapsule_GetPointer(cap, POOL);
    if (!P)
        return;
    for (Py_ssize_t i = 0; i < P->size; i++)
        free(P->e[i].t);
    free(P->e);
    for (Py_ssize_t i = 0; i < P->wn; i++) {
        geo_free(P->w[i].G);
        free(P->w[i].G);
        free(P->w[i].lm);
    }
    free(P->w);
    free(P);
}

static Pool *get_pool(PyObject *cap) { return PyCapsule_GetPointer(cap, POOL); }

/* Insert a copy of `len` terms with this ecart after the entries of equal or lower sugar. */
static int pool_add(Pool *P, const u64 *t, Py_ssize_t len, int ecart)
{
    int W = P->W;
    if (P->size == P->cap) {
        Py_ssize_t cap = P->cap ? 2 * P->cap : 64;
        Entry *e = realloc(P->e, (size_t)cap * sizeof(Entry));
        if (!e)
            return -1;
        P->e = e;
        P->cap = cap;
    }
    Entry x;
    x.len = len;
    x.t = malloc((size_t)(len ? len : 1) * (W + 1) * sizeof(u64));
    if (!x.t)
        return -1;
    memcpy(x.t, t, (size_t)len * (W + 1) * sizeof(u64));
    x.ecart = ecart;
    x.sugar = ecart + deg_of(t);
    x.mask = mask_of(t, P->n);
    Py_ssize_t i = P->size;
    while (i && P->e[i - 1].sugar > x.sugar)
        i--;
    memmove(P->e + i + 1, P->e + i, (size_t)(P->size - i) * sizeof(Entry));
    P->e[i] = x;
    P->size++;
    return 0;
}

/* kernel/mora.py's _choose: the first divisor unless its ecart is too large, else one of
 * least ecart (shorter first), stopping at the first whose ecart is at most `ecart`. */
static Entry *choose(Pool *P, const u64 *lm, int ecart)
{
    int W = P->W;
    u64 mask = mask_of(lm, P->n), guard = P->guard;
    Entry *best = NULL;
    for (Py_ssize_t i = 0; i < P->size; i++) {
        Entry *g = P->e + i;
        if ((g->mask & ~mask) || !divides(g->t, lm, W, guard))
            continue;
        if (!best || g->ecart < best->ecart || (g->ecart == best->ecart && g->len < best->len))
            best = g;
        if (best->ecart <= ecart)
            break;
    }
    return best;
}

static void unit_cancel(Buf *h, int W, u64 guard)
{   /* h = x^a u with x^a = LM(h), u a unit: keep the leading term */
    int S = W + 1;
    if (h->len < 2)
        return;
    for (Py_ssize_t i = 1; i < h->len; i++)
        if (!divides(h->t, h->t + i * S, W, guard))
            return;
    h->len = 1;
}

static PyObject *mora_pool_new(PyObject *self, PyObject *args)
{
    int n;
    unsigned long long p;
    if (!PyArg_ParseTuple(args, "iK", &n, &p))
        return NULL;
    Pool *P = calloc(1, sizeof(Pool));
    if (!P)
        return PyErr_NoMemory();
    P->n = n;
    P->W = (n + 1 + 3) / 4;
    P->p = p;
    P->guard = 0x8000800080008000ULL;
    return PyCapsule_New(P, POOL, pool_free);
}

static PyObject *mora_pool_insert(PyObject *self, PyObject *args)
{
    PyObject *cap;
    Py_buffer buf;
    int ecart;
    if (!PyArg_ParseTuple(args, "Oy*i", &cap, &buf, &ecart))
        return NULL;
    Pool *P = get_pool(cap);
    int rc = P ? pool_add(P, buf.buf, buf.len / (Py_ssize_t)((P->W + 1) * sizeof(u64)), ecart) : -1;
    PyBuffer_Release(&buf);
    if (rc)
        return P ? PyErr_NoMemory() : NULL;
    Py_RETURN_NONE;
}

static PyObject *mora_pool_truncate(PyObject *self, PyObject *args)
{   /* drop the terms of degree above `cut` but the leading ones (Elem.truncate) */
    PyObject *cap;
    int cut;
    if (!PyArg_ParseTuple(args, "Oi", &cap, &cut))
        return NULL;
    Pool *P = get_pool(cap);
    if (!P)
        return NULL;
    int S = P->W + 1;
    for (Py_ssize_t i = 0; i < P->size; i++) {
        Entry *g = P->e + i;
        Py_ssize_t k = 1;
        for (Py_ssize_t j = 1; j < g->len; j++)
            if (deg_of(g->t + j * S) <= cut) {
                if (k != j)
                    memmove(g->t + k * S, g->t + j * S, S * sizeof(u64));
                k++;
            }
        g->len = k;
    }
    Py_RETURN_NONE;
}

static int first_in_queue(int sugar, const u64 *lm, int hsugar, const u64 *hlm, int W)
{   /* (sugar, lm) taken no later than the queue's head (hlm NULL: empty queue) */
    if (!hlm)
        return 1;
    if (sugar != hsugar)
        return sugar < hsugar;
    return cmp_mon(lm, hlm, W) <= 0;
}

/* Whether (sugar, lm, counter) comes before (hs, hm, hc) in the queue (hm NULL: nothing). */
static int before(int sugar, const u64 *lm, long long counter, int hs, const u64 *hm, long long hc, int W)
{
    if (!hm)
        return 1;
    if (sugar != hs)
        return sugar < hs;
    int c = cmp_mon(lm, hm, W);
    return c ? c < 0 : counter < hc;
}

static int wait_less(const Waiting *a, const Waiting *b, int W)
{
    return before(a->sugar, a->lm, a->counter, b->sugar, b->lm, b->counter, W);
}

static int wait_push(Pool *P, Geo *G, int sugar, const u64 *lm, long long counter)
{
    int W = P->W;
    if (P->wn == P->wcap) {
        Py_ssize_t cap = P->wcap ? 2 * P->wcap : 64;
        Waiting *w = realloc(P->w, (size_t)cap * sizeof(Waiting));
        if (!w)
            return -1;
        P->w = w;
        P->wcap = cap;
    }
    Waiting x = {sugar, counter, malloc((size_t)W * sizeof(u64)), G};
    if (!x.lm)
        return -1;
    memcpy(x.lm, lm, (size_t)W * sizeof(u64));
    Py_ssize_t i = P->wn++;
    while (i && wait_less(&x, P->w + (i - 1) / 2, W)) {
        P->w[i] = P->w[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    P->w[i] = x;
    return 0;
}

static Waiting wait_pop(Pool *P)
{
    int W = P->W;
    Waiting top = P->w[0], x = P->w[--P->wn];
    Py_ssize_t i = 0, n = P->wn;
    for (;;) {
        Py_ssize_t c = 2 * i + 1;
        if (c >= n)
            break;
        if (c + 1 < n && wait_less(P->w + c + 1, P->w + c, W))
            c++;
        if (!wait_less(P->w + c, &x, W))
            break;
        P->w[i] = P->w[c];
        i = c;
    }
    if (n)
        P->w[i] = x;
    return top;
}

/* Reduction of G in K[x]/m^(cut+1) (cut >= 0): a finite-dimensional algebra where every step
 * replaces the leading term by smaller terms of a finite set, so it ends without Mora's ecart
 * rule; the first reducer in the pool (by sugar) each time, no postponement: 0 irreducible, 2
 * out of steps, -1 out of memory. */
static int reduce_cut(Pool *P, Geo *G, int cut, long long *steps)
{
    int S = P->W + 1, li;
    geo_trim(G, cut);
    while ((li = geo_lead(G)) >= 0) {
        geo_unit_cancel(G, li, P->guard);
        Entry *g = choose(P, G->b[li].t + G->b[li].start * S, INT_MAX);  /* the first divisor */
        if (!g)
            return 0;
        if (--*steps < 0)
            return 2;
        if (geo_reduce(G, li, g, cut))
            return -1;
    }
    return 0;
}

/* Mora's reduction of G (kernel/mora.py's inner `reduce`): 0 irreducible (maybe zero), 1 to be
 * postponed behind the queue's head (hs, hm; hm NULL: an empty queue), 2 out of steps or
 * degrees, -1 out of memory. */
static int reduce_geo(Pool *P, Geo *G, int *sugar, int hs, const u64 *hm, int cut, long long *steps,
                      int max_sugar)
{
    int W = P->W, S = W + 1;
    u64 guard = P->guard;
    int limit = *sugar + LAZY_DEGREE, passes = 0, li;
    geo_trim(G, cut);
    while ((li = geo_lead(G)) >= 0) {
        geo_unit_cancel(G, li, guard);
        const u64 *lm = G->b[li].t + G->b[li].start * S;
        int ecart = *sugar - deg_of(lm);
        Entry *g = choose(P, lm, ecart);
        if (!g)
            return 0;
        if (--*steps < 0)
            return 2;
        if (g->ecart > ecart) {
            if (!first_in_queue(*sugar, lm, hs, hm, W))
                return 1;
            Py_ssize_t gi = g - P->e;
            u64 *gt = g->t;
            if (geo_flatten(G) || pool_add(P, G->b[NB - 1].t + G->b[NB - 1].start * S,
                                           G->b[NB - 1].len - G->b[NB - 1].start, ecart))
                return -1;
            li = NB - 1;
            g = P->e + gi;  /* the array may have moved, and g one place up */
            if (g->t != gt)
                g++;
            *sugar += g->ecart - ecart;
            if (*sugar > max_sugar)
                return 2;
        }
        if (geo_reduce(G, li, g, cut))
            return -1;
        if ((li = geo_lead(G)) < 0)
            break;
        passes++;
        if (*sugar >= limit || passes > LAZY_PASS) {
            lm = G->b[li].t + G->b[li].start * S;
            if (!first_in_queue(*sugar, lm, hs, hm, W))
                return choose(P, lm, *sugar - deg_of(lm)) ? 1 : 0;
        }
    }
    return 0;
}

static void geo_release(Geo *G)
{
    geo_free(G);
    free(G);
}

/* run(pool, h or None, sugar, head_sugar, head_lm or None, head_counter, cut, steps, counter)
 *   -> (status, h, sugar, steps left, counter, waiting): the queue of kernel/mora.py's _mora,
 *   its postponed polynomials kept here.  h (bytes, with its sugar) is reduced first; None:
 *   start with the first postponed polynomial if it comes before the queue's head (head_lm
 *   None: the queue is empty).  A postponed polynomial waits here under the next counter; the
 *   loop goes on with whatever comes first.  Status 0: an irreducible nonzero h (bytes) with its
 *   sugar; 2: budget spent or degree too large; 3: the queue's head comes first (or nothing is
 *   left).  `waiting`: how many polynomials wait here. */
static PyObject *mora_run(PyObject *self, PyObject *args)
{
    PyObject *cap, *hobj, *headobj;
    int sugar, hs, cut, max_sugar;
    long long hc, steps, counter;
    if (!PyArg_ParseTuple(args, "OOiiOLiLLi", &cap, &hobj, &sugar, &hs, &headobj, &hc, &cut, &steps, &counter,
                          &max_sugar))
        return NULL;
    Pool *P = get_pool(cap);
    if (!P)
        return NULL;
    int W = P->W, S = W + 1;
    const u64 *hm = NULL;
    Py_buffer headb;
    if (headobj != Py_None) {
        if (PyObject_GetBuffer(headobj, &headb, PyBUF_SIMPLE))
            return NULL;
        hm = headb.buf;
    }
    Geo *G = NULL;
    int status = 3;
    if (hobj != Py_None) {
        Py_buffer hb;
        if (PyObject_GetBuffer(hobj, &hb, PyBUF_SIMPLE))
            goto fail;
        G = calloc(1, sizeof(Geo));
        Py_ssize_t len = hb.len / (Py_ssize_t)(S * sizeof(u64));
        if (G) {
            G->W = W; G->S = S; G->p = P->p;
        }
        int rc = !G || (len && geo_merge(G, NB - 1, hb.buf, len));
        PyBuffer_Release(&hb);
        if (rc) {
            if (G)
                geo_release(G);
            PyErr_NoMemory();
            goto fail;
        }
    }
    for (;;) {
        if (!G) {
            if (!P->wn || !before(P->w[0].sugar, P->w[0].lm, P->w[0].counter, hs, hm, hc, W))
                break;
            Waiting x = wait_pop(P);
            G = x.G;
            sugar = x.sugar;
            free(x.lm);
        }
        /* the head of the whole queue: the Python one's or the first waiting here */
        int es = hs;
        const u64 *em = hm;
        if (P->wn && before(P->w[0].sugar, P->w[0].lm, P->w[0].counter, hs, hm, hc, W)) {
            es = P->w[0].sugar;
            em = P->w[0].lm;
        }
        int rc = cut >= 0 ? reduce_cut(P, G, cut, &steps) : reduce_geo(P, G, &sugar, es, em, cut, &steps,
                                                       max_sugar < MAX_DEGREE ? max_sugar : MAX_DEGREE);
        if (rc < 0) {
            geo_release(G);
            PyErr_NoMemory();
            goto fail;
        }
        if (rc == 2) {
            geo_release(G);
            status = 2;
            break;
        }
        if (rc == 1) {
            int li = geo_lead(G);
            if (wait_push(P, G, sugar, G->b[li].t + G->b[li].start * S, ++counter)) {
                geo_release(G);
                PyErr_NoMemory();
                goto fail;
            }
            G = NULL;
            continue;
        }
        if (geo_flatten(G)) {
            geo_release(G);
            PyErr_NoMemory();
            goto fail;
        }
        Bucket *B = G->b + NB - 1;
        if (B->len > B->start) {
            PyObject *out = PyBytes_FromStringAndSize((const char *)(B->t + B->start * S),
                                                      (B->len - B->start) * S * (Py_ssize_t)sizeof(u64));
            geo_release(G);
            if (!out)
                goto fail;
            if (hm)
                PyBuffer_Release(&headb);
            return Py_BuildValue("(iNiLLn)", 0, out, sugar, steps, counter, P->wn);
        }
        geo_release(G);
        G = NULL;
    }
    if (hm)
        PyBuffer_Release(&headb);
    return Py_BuildValue("(iOiLLn)", status, Py_None, sugar, steps, counter, P->wn);
fail:
    if (hm)
        PyBuffer_Release(&headb);
    return NULL;
}

/* spoly(f, g, n, p, cut): lc(g) x^(l - lm f) f - lc(f) x^(l - lm g) g for l = lcm(lm f, lm g),
 * terms of degree above `cut` left out (cut < 0: none); None when a degree passes 2^15 - 1. */
static PyObject *mora_spoly(PyObject *self, PyObject *args)
{
    Py_buffer fb, gb;
    int n, cut;
    unsigned long long p;
    if (!PyArg_ParseTuple(args, "y*y*iKi", &fb, &gb, &n, &p, &cut))
        return NULL;
    int W = (n + 4) / 4, S = W + 1;
    const u64 *f = fb.buf, *g = gb.buf;
    Py_ssize_t nf = fb.len / (S * (Py_ssize_t)sizeof(u64)), ng = gb.len / (S * (Py_ssize_t)sizeof(u64));
    u64 sf[16], sg[16], lcm[16];
    /* the lcm field by field (the degree field recomputed from the exponents) */
    int degree = 0;
    for (int i = 0; i < W; i++) {
        u64 w = 0;
        for (int k = 0; k < 4; k++) {
            int field = 4 * i + k, shift = 48 - 16 * k;
            if (field == 0 || field > n)
                continue;
            u64 a = (f[i] >> shift) & 0xffff, b = (g[i] >> shift) & 0xffff, m = a > b ? a : b;
            degree += (int)m;
            w |= m << shift;
        }
        lcm[i] = w;
    }
    lcm[0] |= (u64)degree << 48;
    for (int i = 0; i < W; i++) {
        sf[i] = lcm[i] - f[i];
        sg[i] = lcm[i] - g[i];
    }
    u64 cf = f[W], cg = g[W];
    u64 *out = malloc((size_t)(nf + ng + 1) * S * sizeof(u64));
    if (!out) {
        PyBuffer_Release(&fb);
        PyBuffer_Release(&gb);
        return PyErr_NoMemory();
    }
    Py_ssize_t a = 0, b = 0, k = 0;
    int overflow = 0;
    u64 ma[16], mb[16];
    while (a < nf || b < ng) {
        if (a < nf)
            for (int i = 0; i < W; i++)
                ma[i] = f[a * S + i] + sf[i];
        if (b < ng)
            for (int i = 0; i < W; i++)
                mb[i] = g[b * S + i] + sg[i];
        int c = a >= nf ? 1 : b >= ng ? -1 : cmp_mon(ma, mb, W);
        u64 v, *m;
        if (c < 0) {
            v = (f[a * S + W] * cg) % p;
            m = ma;
            a++;
        } else if (c > 0) {
            v = (g[b * S + W] * cf) % p;
            v = v ? p - v : 0;
            m = mb;
            b++;
        } else {
            u64 x = (f[a * S + W] * cg) % p, y = (g[b * S + W] * cf) % p;
            v = x >= y ? x - y : x + p - y;
            m = ma;
            a++; b++;
        }
        if (deg_of(m) > MAX_DEGREE)
            overflow = 1;
        if (v && (cut < 0 || deg_of(m) <= cut)) {
            memcpy(out + k * S, m, W * sizeof(u64));
            out[k * S + W] = v;
            k++;
        }
    }
    PyBuffer_Release(&fb);
    PyBuffer_Release(&gb);
    if (overflow) {
        free(out);
        Py_RETURN_NONE;
    }
    PyObject *res = PyBytes_FromStringAndSize((const char *)out, k * S * (Py_ssize_t)sizeof(u64));
    free(out);
    return res;
}

static int cmp_terms_W;
static int cmp_terms(const void *a, const void *b) { return cmp_mon(a, b, cmp_terms_W); }

/* pack(n, terms): `bytes` of the terms [(exponent tuple, coefficient in [0, p)), ...], sorted
 * leading first; None if an exponent or the degree reaches 2^15. */
static PyObject *mora_pack(PyObject *self, PyObject *args)
{
    int n;
    PyObject *terms;
    if (!PyArg_ParseTuple(args, "iO!", &n, &PyList_Type, &terms))
        return NULL;
    int W = (n + 4) / 4, S = W + 1;
    Py_ssize_t len = PyList_GET_SIZE(terms);
    u64 *t = calloc((size_t)(len ? len : 1) * S, sizeof(u64));
    if (!t)
        return PyErr_NoMemory();
    for (Py_ssize_t j = 0; j < len; j++) {
        PyObject *item = PyList_GET_ITEM(terms, j), *e;
        if (!PyTuple_Check(item) || PyTuple_GET_SIZE(item) != 2 || !PyTuple_Check(e = PyTuple_GET_ITEM(item, 0))
                || PyTuple_GET_SIZE(e) != n) {
            free(t);
            PyErr_SetString(PyExc_TypeError, "pack: (exponent tuple, coefficient) expected");
            return NULL;
        }
        u64 *m = t + j * S;
        long degree = 0;
        for (int i = 0; i < n; i++) {
            long v = PyLong_AsLong(PyTuple_GET_ITEM(e, i));
            if (v < 0 || v > MAX_DEGREE) {
                free(t);
                if (PyErr_Occurred())
                    return NULL;
                Py_RETURN_NONE;
            }
            degree += v;
            int field = n - i;
            m[field / 4] |= (u64)v << (48 - 16 * (field % 4));
        }
        if (degree > MAX_DEGREE) {
            free(t);
            Py_RETURN_NONE;
        }
        m[0] |= (u64)degree << 48;
        m[W] = PyLong_AsUnsignedLongLong(PyTuple_GET_ITEM(item, 1));
        if (PyErr_Occurred()) {
            free(t);
            return NULL;
        }
    }
    cmp_terms_W = W;
    qsort(t, (size_t)len, S * sizeof(u64), cmp_terms);
    PyObject *res = PyBytes_FromStringAndSize((const char *)t, len * S * (Py_ssize_t)sizeof(u64));
    free(t);
    return res;
}

/* unpack(n, b): [(exponent tuple, coefficient), ...] leading first. */
static PyObject *mora_unpack(PyObject *self, PyObject *args)
{
    int n;
    Py_buffer b;
    if (!PyArg_ParseTuple(args, "iy*", &n, &b))
        return NULL;
    int W = (n + 4) / 4, S = W + 1;
    const u64 *t = b.buf;
    Py_ssize_t len = b.len / (S * (Py_ssize_t)sizeof(u64));
    PyObject *out = PyList_New(len);
    for (Py_ssize_t j = 0; out && j < len; j++) {
        PyObject *e = PyTuple_New(n);
        if (!e) {
            Py_CLEAR(out);
            break;
        }
        for (int i = 0; i < n; i++) {
            int field = n - i;
            PyTuple_SET_ITEM(e, i, PyLong_FromUnsignedLongLong((t[j * S + field / 4] >> (48 - 16 * (field % 4))) & 0xffff));
        }
        PyObject *item = Py_BuildValue("(NK)", e, (unsigned long long)t[j * S + W]);
        if (!item) {
            Py_CLEAR(out);
            break;
        }
        PyList_SET_ITEM(out, j, item);
    }
    PyBuffer_Release(&b);
    return out;
}

/* normalize(n, p, b): h = x^a u (x^a = LM(h), u a unit) replaced by its leading term, then made
 * monic; -> (h, its largest degree, the second monomial's index or -1). */
static PyObject *mora_normalize(PyObject *self, PyObject *args)
{
    int n;
    unsigned long long p;
    Py_buffer b;
    if (!PyArg_ParseTuple(args, "iKy*", &n, &p, &b))
        return NULL;
    int W = (n + 4) / 4, S = W + 1;
    Buf h = {0, 0, NULL};
    Py_ssize_t len = b.len / (S * (Py_ssize_t)sizeof(u64));
    if (buf_reserve(&h, len + 1, W)) {
        PyBuffer_Release(&b);
        return PyErr_NoMemory();
    }
    memcpy(h.t, b.buf, (size_t)len * S * sizeof(u64));
    PyBuffer_Release(&b);
    h.len = len;
    unit_cancel(&h, W, 0x8000800080008000ULL);
    int top = 0;
    if (h.len) {
        u64 inv = inv_mod(h.t[W], p);
        for (Py_ssize_t i = 0; i < h.len; i++) {
            h.t[i * S + W] = (h.t[i * S + W] * inv) % p;
            if (deg_of(h.t + i * S) > top)
                top = deg_of(h.t + i * S);
        }
    }
    PyObject *out = PyBytes_FromStringAndSize((const char *)h.t, h.len * S * (Py_ssize_t)sizeof(u64));
    free(h.t);
    if (!out)
        return NULL;
    return Py_BuildValue("(Ni)", out, top);
}

/* truncate(n, b, cut): the terms of degree above `cut` dropped but the leading one. */
static PyObject *mora_truncate(PyObject *self, PyObject *args)
{
    int n, cut;
    Py_buffer b;
    if (!PyArg_ParseTuple(args, "iy*i", &n, &b, &cut))
        return NULL;
    int W = (n + 4) / 4, S = W + 1;
    const u64 *t = b.buf;
    Py_ssize_t len = b.len / (S * (Py_ssize_t)sizeof(u64)), k = 0;
    u64 *out = malloc((size_t)(len ? len : 1) * S * sizeof(u64));
    if (!out) {
        PyBuffer_Release(&b);
        return PyErr_NoMemory();
    }
    for (Py_ssize_t i = 0; i < len; i++)
        if (i == 0 || deg_of(t + i * S) <= cut)
            memcpy(out + (k++) * S, t + i * S, S * sizeof(u64));
    PyBuffer_Release(&b);
    PyObject *res = PyBytes_FromStringAndSize((const char *)out, k * S * (Py_ssize_t)sizeof(u64));
    free(out);
    return res;
}

static PyMethodDef methods[] = {
    {"normalize", mora_normalize, METH_VARARGS, "normalize(n, p, b): unit cancelled, monic; largest degree."},
    {"truncate", mora_truncate, METH_VARARGS, "truncate(n, b, cut): tail terms above cut dropped."},
    {"pool_new", mora_pool_new, METH_VARARGS, "pool_new(n, p): an empty pool of reducers."},
    {"pool_insert", mora_pool_insert, METH_VARARGS, "pool_insert(pool, terms, ecart): add a reducer."},
    {"pool_truncate", mora_pool_truncate, METH_VARARGS, "pool_truncate(pool, cut): drop tails above cut."},
    {"run", mora_run, METH_VARARGS, "Mora's reduction loop and its postponed polynomials (see the source)."},
    {"spoly", mora_spoly, METH_VARARGS, "spoly(f, g, n, p, cut): the S-polynomial."},
    {"pack", mora_pack, METH_VARARGS, "pack(n, terms): terms as bytes, leading first."},
    {"unpack", mora_unpack, METH_VARARGS, "unpack(n, b): the terms of bytes."},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_mora", "Mora's normal form for ds over Z/p.", -1,
                                    methods};

PyMODINIT_FUNC PyInit__mora(void)
{
    return PyModule_Create(&module);
}
