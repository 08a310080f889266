/* Polynomials of kernel/_mora.c: packed monomials (the layout is described there), the
 * reducers' entries, growable term arrays and the geobucket of the polynomial under reduction. */
#ifndef MECH_MORA_POLY_H
#define MECH_MORA_POLY_H

#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef uint64_t u64;

typedef struct {
    int sugar, ecart;
    u64 mask;
    Py_ssize_t len;
    u64 *t;          /* len * (W + 1) words */
} Entry;


/* A growable polynomial under reduction. */
typedef struct {
    Py_ssize_t len, cap;
    u64 *t;
} Buf;

#define LAZY_DEGREE 1
#define LAZY_PASS 2
#define MAX_DEGREE 32767

static int deg_of(const u64 *m) { return (int)(m[0] >> 48); }

static int cmp_mon(const u64 *a, const u64 *b, int W)
{
    for (int i = 0; i < W; i++) {
        if (a[i] != b[i])
            return a[i] < b[i] ? -1 : 1;
    }
    return 0;
}

static int divides(const u64 *b, const u64 *a, int W, u64 guard)
{   /* whether the monomial b divides a */
    for (int i = 0; i < W; i++)
        if ((((a[i] | guard) - b[i]) & guard) != guard)
            return 0;
    return 1;
}

static u64 mask_of(const u64 *m, int n)
{   /* bit i for variable x_{i+1} (mod 64) with a positive exponent */
    u64 mask = 0;
    for (int i = 0; i < n; i++) {
        int field = n - i;          /* field 0 is the degree, field n - i holds x_{i+1} */
        u64 v = (m[field / 4] >> (48 - 16 * (field % 4))) & 0xffff;
        if (v)
            mask |= (u64)1 << (i % 64);
    }
    return mask;
}

static u64 inv_mod(u64 a, u64 p)
{
    int64_t t = 0, nt = 1, r = (int64_t)p, nr = (int64_t)a, q, tmp;
    while (nr) {
        q = r / nr;
        tmp = t - q * nt; t = nt; nt = tmp;
        tmp = r - q * nr; r = nr; nr = tmp;
    }
    return (u64)(t < 0 ? t + (int64_t)p : t);
}

static int buf_reserve(Buf *b, Py_ssize_t terms, int W)
{
    if (terms <= b->cap)
        return 0;
    Py_ssize_t cap = b->cap ? b->cap : 16;
    while (cap < terms)
        cap *= 2;
    u64 *t = realloc(b->t, (size_t)cap * (W + 1) * sizeof(u64));
    if (!t)
        return -1;
    b->t = t;
    b->cap = cap;
    return 0;
}

/* The polynomial under reduction as a geobucket (Yan): buckets of sorted arrays, bucket i
 * holding at most 16 * 4^i terms (the last one any number); adding a multiple of a reducer
 * merges it into a bucket of its size, so a step costs about the reducer's length. */
#define NB 12

typedef struct {
    Py_ssize_t start, len, cap;   /* terms t[start..len) */
    u64 *t;
} Bucket;

typedef struct {
    int W, S;
    u64 p;
    unsigned used;       /* bit i set for every bucket i holding terms (maybe for some empty ones) */
    Bucket b[NB];
    Buf tmp, q;
} Geo;

/* A polynomial postponed by the reduction loop, waiting for its turn in the queue. */
typedef struct {
    int sugar;
    long long counter;   /* the queue's tie-break: earlier first */
    u64 *lm;             /* W words */
    Geo *G;
} Waiting;

typedef struct {
    int n, W;
    u64 p, guard;
    Py_ssize_t size, cap;
    Entry *e;
    Py_ssize_t wn, wcap;  /* the postponed polynomials, a binary heap by (sugar, lm, counter) */
    Waiting *w;
} Pool;

static Py_ssize_t bucket_cap(int i) { return i == NB - 1 ? PY_SSIZE_T_MAX : (Py_ssize_t)16 << (2 * i); }

static void geo_free(Geo *G)
{
    for (int i = 0; i < NB; i++)
        free(G->b[i].t);
    free(G->tmp.t);
    free(G->q.t);
}

/* Copy `words` words (one term or monomial: a few words, too short for a call to memcpy). */
static inline void copy_words(u64 *dst, const u64 *src, int words)
{
    for (int j = 0; j < words; j++)
        dst[j] = src[j];
}

/* Merge the sorted terms q[0..n) into bucket i (coefficients added, zeros dropped). */
static int geo_merge(Geo *G, int i, const u64 *q, Py_ssize_t n)
{
    int W = G->W, S = G->S;
    u64 p = G->p;
    Bucket *B = G->b + i;
    Py_ssize_t blen = B->len - B->start;
    if (buf_reserve(&G->tmp, blen + n, W))
        return -1;
    const u64 *a = B->t ? B->t + B->start * S : NULL;
    Py_ssize_t x = 0, y = 0, k = 0;
    u64 *out = G->tmp.t;
    while (x < blen && y < n) {
        int c = cmp_mon(a + x * S, q + y * S, W);
        if (c < 0) {
            copy_words(out + k++ * S, a + x++ * S, S);
        } else if (c > 0) {
            copy_words(out + k++ * S, q + y++ * S, S);
        } else {
            u64 v = a[x * S + W] + q[y * S + W];
            if (v >= p)
                v -= p;
            if (v) {
                copy_words(out + k * S, a + x * S, W);
                out[k++ * S + W] = v;
            }
            x++; y++;
        }
    }
    if (x < blen) {
        memcpy(out + k * S, a + x * S, (size_t)(blen - x) * S * sizeof(u64));
        k += blen - x;
    }
    if (y < n) {
        memcpy(out + k * S, q + y * S, (size_t)(n - y) * S * sizeof(u64));
        k += n - y;
    }
    /* swap the bucket's array with the merged one */
    u64 *t = B->t;
    Py_ssize_t cap = B->cap;
    B->t = G->tmp.t; B->cap = G->tmp.cap; B->start = 0; B->len = k;
    G->tmp.t = t; G->tmp.cap = cap;
    if (k)
        G->used |= 1u << i;
    return 0;
}

/* Add the sorted terms q[0..n) to the geobucket. */
static int geo_add(Geo *G, const u64 *q, Py_ssize_t n)
{
    int i = 0;
    while (n > bucket_cap(i))
        i++;
    if (geo_merge(G, i, q, n))
        return -1;
    while (G->b[i].len - G->b[i].start > bucket_cap(i)) {
        Bucket *B = G->b + i;
        /* move bucket i up: its array becomes q's source, then emptied */
        if (buf_reserve(&G->q, B->len - B->start, G->W))
            return -1;
        memcpy(G->q.t, B->t + B->start * G->S, (size_t)(B->len - B->start) * G->S * sizeof(u64));
        Py_ssize_t m = B->len - B->start;
        B->start = B->len = 0;
        if (geo_merge(G, i + 1, G->q.t, m))
            return -1;
        i++;
    }
    return 0;
}

/* The bucket whose head is the leading term (equal heads summed into it, zero sums dropped);
 * -1 when the polynomial is zero. */
static int geo_lead(Geo *G)
{
    int W = G->W, S = G->S;
    u64 p = G->p;
    for (;;) {
        int best = -1;
        for (unsigned m = G->used; m; m &= m - 1) {
            int i = __builtin_ctz(m);
            Bucket *B = G->b + i;
            if (B->start == B->len) {
                G->used &= ~(1u << i);
                continue;
            }
            if (best < 0 || cmp_mon(B->t + B->start * S, G->b[best].t + G->b[best].start * S, W) < 0)
                best = i;
        }
        if (best < 0)
            return -1;
        u64 *lead = G->b[best].t + G->b[best].start * S;
        u64 v = lead[W];
        for (unsigned m = G->used; m; m &= m - 1) {
            int i = __builtin_ctz(m);
            Bucket *B = G->b + i;
            if (i == best || B->start == B->len || cmp_mon(B->t + B->start * S, lead, W))
                continue;
            v += B->t[B->start * S + W];
            if (v >= p)
                v -= p;
            B->start++;
        }
        if (v) {
            lead[W] = v;
            return best;
        }
        G->b[best].start++;
    }
}

/* Everything merged into the last bucket (its terms then are the polynomial, sorted). */
static int geo_flatten(Geo *G)
{
    for (int i = 0; i < NB - 1; i++) {
        Bucket *B = G->b + i;
        Py_ssize_t m = B->len - B->start;
        if (!m)
            continue;
        if (buf_reserve(&G->q, m, G->W))
            return -1;
        memcpy(G->q.t, B->t + B->start * G->S, (size_t)m * G->S * sizeof(u64));
        B->start = B->len = 0;
        if (geo_merge(G, NB - 1, G->q.t, m))
            return -1;
    }
    return 0;
}

static void geo_trim(Geo *G, int cut)
{
    if (cut < 0)
        return;
    int S = G->S;
    for (int i = 0; i < NB; i++) {
        Bucket *B = G->b + i;
        Py_ssize_t k = B->start;
        for (Py_ssize_t j = B->start; j < B->len; j++)
            if (deg_of(B->t + j * S) <= cut) {
                if (k != j)
                    memmove(B->t + k * S, B->t + j * S, S * sizeof(u64));
                k++;
            }
        B->len = k;
    }
}

/* h = x^a u with x^a = LM(h) (the head of bucket `li`), u a unit: keep the leading term. */
static void geo_unit_cancel(Geo *G, int li, u64 guard)
{
    int W = G->W, S = G->S;
    const u64 *lead = G->b[li].t + G->b[li].start * S;
    for (int i = 0; i < NB; i++) {
        Bucket *B = G->b + i;
        for (Py_ssize_t j = B->start + (i == li); j < B->len; j++)
            if (!divides(lead, B->t + j * S, W, guard))
                return;
    }
    for (int i = 0; i < NB; i++)
        if (i != li)
            G->b[i].start = G->b[i].len = 0;
    G->b[li].len = G->b[li].start + 1;
}

/* h := h - (lc(h) / lc(g)) x^(lm(h) - lm(g)) g with the leading term at the head of bucket `li`,
 * terms of degree above `cut` left out (cut < 0: none). */
static int geo_reduce(Geo *G, int li, const Entry *g, int cut)
{
    int W = G->W, S = G->S;
    u64 p = G->p;
    u64 *lead = G->b[li].t + G->b[li].start * S;
    u64 shift[16];
    for (int i = 0; i < W; i++)
        shift[i] = lead[i] - g->t[i];
    u64 f = (lead[W] * inv_mod(g->t[W], p)) % p;
    G->b[li].start++;          /* the leading terms cancel */
    if (buf_reserve(&G->q, g->len, W))
        return -1;
    Py_ssize_t k = 0;
    for (Py_ssize_t j = 1; j < g->len; j++) {
        u64 *out = G->q.t + k * S;
        for (int i = 0; i < W; i++)
            out[i] = g->t[j * S + i] + shift[i];
        if (cut >= 0 && deg_of(out) > cut)
            break;              /* sorted by degree first: the rest lies above the cut */
        u64 v = (f * g->t[j * S + W]) % p;
        out[W] = v ? p - v : 0;
        if (out[W])
            k++;
    }
    return k ? geo_add(G, G->q.t, k) : 0;
}

#endif
