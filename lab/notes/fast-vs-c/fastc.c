/*
 * Experiment: the fast engine's algorithm in C, for a same-machine comparison with the JVM.
 * A line-by-line port of DiscTable, CellPredictor, CalendarQueue and FastRun (commit ca94c87) for
 * the case GasBench measures: periodic box, equal discs, straight flight, elastic, >= 4 cells per
 * axis. Same arithmetic in the same order, so the same collisions (checked against Java's count).
 * Build: gcc -O3 -march=native -ffp-contract=off -o fastc fastc.c -lm
 * Run:   ./fastc gas.bin [REPEATS [WARMUPS]]
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { X, Y, VX, VY, T, EV, ST };
enum { CELL, PARTNER, PCOUNT, COUNT, CNEXT, QNEXT, QPREV, IS };
enum { HIT = 0, CROSS_LEFT = 1, CROSS_RIGHT = 2, CROSS_DOWN = 3, CROSS_UP = 4 };
#define NIL (-1)
#define NONE INT32_MIN
#define AXIS_BITS 14
#define AXIS_MASK ((1 << AXIS_BITS) - 1)
#define CELL_MASK ((1 << (2 * AXIS_BITS)) - 1)
#define KIND_SHIFT (2 * AXIS_BITS)
#define SPAN_MEANS 4.0
#define RESYNC_SPANS 4.0
#define INF (1.0 / 0.0)
#define GRAZING 1e-10
#define MAX_SLICE (1LL << 60)

static int n, cols, rows;
static double width, height, cellW, cellH, radius, invMass, until;
static double *rec;
static int *ir, *cellHead, *sceneIds;
static int around[9], ahead[5][3];
static double *sx, *sy, *svx, *svy; /* the scene */

/* ---- calendar queue ---- */
static int *qhead, buckets, qmask, *heap, heapCap, heapSize, inBuckets, idle;
static double qwidth, invWidth;
static long long cur;

static inline long long sliceOf(double t) {
    double x = t * invWidth;
    long long s = x >= 9.2e18 ? MAX_SLICE : (long long) x;
    return s < MAX_SLICE ? s : MAX_SLICE;
}
static inline double qtime(int i) { return rec[i * ST + EV]; }
static inline void siftUp(int k, int i) {
    double t = qtime(i);
    while (k > 0) {
        int parent = (k - 1) >> 1;
        int p = heap[parent];
        if (qtime(p) <= t) break;
        heap[k] = p;
        k = parent;
    }
    heap[k] = i;
}
static inline void siftDown(int k, int i) {
    double t = qtime(i);
    int size = heapSize, half = size >> 1;
    while (k < half) {
        int child = 2 * k + 1;
        int c = heap[child];
        double ct = qtime(c);
        int right = child + 1;
        if (right < size && qtime(heap[right]) < ct) {
            child = right;
            c = heap[child];
            ct = qtime(c);
        }
        if (t <= ct) break;
        heap[k] = c;
        k = child;
    }
    heap[k] = i;
}
static inline void heapPush(int i) {
    if (heapSize == heapCap) {
        heapCap *= 2;
        heap = realloc(heap, sizeof(int) * heapCap);
    }
    siftUp(heapSize++, i);
}
static inline void heapRemoveAt(int k) {
    int last = heap[--heapSize];
    if (k == heapSize) return;
    double t = qtime(last);
    if (k > 0 && qtime(heap[(k - 1) >> 1]) > t) siftUp(k, last);
    else siftDown(k, last);
}
static inline void qpush(int b, int i) {
    int h = qhead[b];
    ir[i * IS + QNEXT] = h;
    ir[i * IS + QPREV] = NIL;
    if (h != NIL) ir[h * IS + QPREV] = i;
    qhead[b] = i;
}
static inline void qunlink(int list, int i) {
    int before = ir[i * IS + QPREV], after = ir[i * IS + QNEXT];
    if (before == NIL) qhead[list] = after;
    else ir[before * IS + QNEXT] = after;
    if (after != NIL) ir[after * IS + QPREV] = before;
}
static inline void place(int i) {
    long long s = sliceOf(qtime(i));
    if (s <= cur) heapPush(i);
    else {
        qpush((int) (s & qmask), i);
        inBuckets++;
    }
}
static void qrebuild(double newWidth, double now) {
    qwidth = newWidth;
    invWidth = 1 / newWidth;
    for (int b = 0; b < buckets; b++) qhead[b] = NIL;
    heapSize = inBuckets = idle = 0;
    cur = sliceOf(now);
    for (int i = 0; i < n; i++)
        if (qtime(i) != INF) place(i);
}
static inline void qinsert(int i, double t) {
    rec[i * ST + EV] = t;
    if (t != INF) place(i);
}
static inline void qremove(int i) {
    double t = qtime(i);
    if (t == INF) return;
    if (sliceOf(t) <= cur) {
        int k = 0;
        while (heap[k] != i) k++;
        heapRemoveAt(k);
    } else {
        qunlink((int) (sliceOf(t) & qmask), i);
        inBuckets--;
    }
    rec[i * ST + EV] = INF;
}
static void drain(int b) {
    int i = qhead[b];
    qhead[b] = NIL;
    while (i != NIL) {
        int following = ir[i * IS + QNEXT];
        if (sliceOf(qtime(i)) <= cur) {
            heapPush(i);
            inBuckets--;
            idle = 0;
        } else qpush(b, i);
        i = following;
    }
}
static long long earliestSlice(void) {
    long long e = MAX_SLICE;
    for (int b = 0; b < buckets; b++)
        for (int i = qhead[b]; i != NIL; i = ir[i * IS + QNEXT]) {
            long long s = sliceOf(qtime(i));
            if (s < e) e = s;
        }
    return e;
}
static inline int qpeek(void) {
    while (heapSize == 0) {
        if (inBuckets == 0) return NIL;
        if (++idle > buckets) {
            cur = earliestSlice() - 1;
            idle = 0;
        }
        cur++;
        drain((int) (cur & qmask));
    }
    return heap[0];
}
static inline void qpollTop(void) {
    int i = heap[0];
    heapRemoveAt(0);
    rec[i * ST + EV] = INF;
}

/* ---- physics ---- */
static inline double sepX(double dx) { return dx - width * rint(dx * (1 / width)); }
static inline double sepY(double dy) { return dy - height * rint(dy * (1 / height)); }
static inline double timeToContact(double dx, double dy, double dvx, double dvy, double sigma) {
    double b = dx * dvx + dy * dvy;
    if (b >= 0) return INF;
    double r2 = dx * dx + dy * dy;
    double c = r2 - sigma * sigma;
    double v2 = dvx * dvx + dvy * dvy;
    if (c <= 0) return (b < 0 && b * b > GRAZING * GRAZING * r2 * v2) ? 0 : INF;
    double disc = b * b - v2 * c;
    if (disc <= 0) return INF;
    return c / (sqrt(disc) - b);
}

/* ---- predictor ---- */
static double found;
static int foundP;
static int crossKind;
static long long predictions, events, pairCollisions, crossings, staleEvents, resyncs;
static int visitCell[9];
static double visitShiftX[9], visitShiftY[9];
static int heads[9];

static inline void advance(int i, double time) {
    int at = i * ST;
    double dt = time - rec[at + T];
    rec[at + X] += rec[at + VX] * dt;
    rec[at + Y] += rec[at + VY] * dt;
    rec[at + T] = time;
}
static inline double crossing(int i, double now) {
    int packed = ir[i * IS + CELL];
    int col = packed & AXIS_MASK, row = (packed >> AXIS_BITS) & AXIS_MASK;
    double loX = col > 0 ? col * cellW : 0;
    double hiX = col < cols - 1 ? (col + 1) * cellW : width;
    double loY = row > 0 ? row * cellH : 0;
    double hiY = row < rows - 1 ? (row + 1) * cellH : height;
    int at = i * ST;
    double vx = rec[at + VX], vy = rec[at + VY];
    double dt = now - rec[at + T];
    double x = rec[at + X] + vx * dt, y = rec[at + Y] + vy * dt;
    double tx = vx > 0 ? fmax(0, (hiX - x) / vx) : (vx < 0 ? fmax(0, (loX - x) / vx) : INF);
    double ty = vy > 0 ? fmax(0, (hiY - y) / vy) : (vy < 0 ? fmax(0, (loY - y) / vy) : INF);
    if (tx <= ty) {
        crossKind = vx > 0 ? CROSS_RIGHT : CROSS_LEFT;
        return tx;
    }
    crossKind = vy > 0 ? CROSS_UP : CROSS_DOWN;
    return ty;
}
static inline int interior(int col, int row) { return col > 0 && col < cols - 1 && row > 0 && row < rows - 1; }
static inline int visit(int c, int r, int m) {
    double shiftX = 0, shiftY = 0;
    if (c < 0 || c >= cols) {
        shiftX = c < 0 ? -width : width;
        c = c < 0 ? c + cols : c - cols;
    }
    if (r < 0 || r >= rows) {
        shiftY = r < 0 ? -height : height;
        r = r < 0 ? r + rows : r - rows;
    }
    visitCell[m] = r * cols + c;
    visitShiftX[m] = shiftX;
    visitShiftY[m] = shiftY;
    return m + 1;
}
static const double NO_SHIFT[9];
static inline void scan(int i, double now, int base, const int *cells, const double *shX, const double *shY, int m) {
    double best = found;
    int bestP = foundP;
    for (int k = 0; k < m; k++) heads[k] = cellHead[base + cells[k]];
    int at = i * ST;
    double vxi = rec[at + VX], vyi = rec[at + VY];
    double xi = rec[at + X] + vxi * (now - rec[at + T]);
    double yi = rec[at + Y] + vyi * (now - rec[at + T]);
    double sigma = radius + radius;
    for (int k = 0; k < m; k++) {
        double ox = xi - shX[k], oy = yi - shY[k];
        for (int j = heads[k]; j != NIL; j = ir[j * IS + CNEXT]) {
            if (j != i) {
                int jt = j * ST;
                double dt = now - rec[jt + T];
                double vxj = rec[jt + VX], vyj = rec[jt + VY];
                double t = timeToContact(rec[jt + X] + vxj * dt - ox, rec[jt + Y] + vyj * dt - oy, vxj - vxi,
                                         vyj - vyi, sigma);
                if (t < best) {
                    best = t;
                    bestP = j;
                }
            }
        }
    }
    found = best;
    foundP = bestP;
}
static inline double schedule(int i, double now, double best, int bestP, double cross, int ck) {
    ir[i * IS + PARTNER] = bestP;
    ir[i * IS + PCOUNT] = bestP >= 0 ? ir[bestP * IS + COUNT] : 0;
    if (cross < best) {
        ir[i * IS + CELL] = (ir[i * IS + CELL] & CELL_MASK) | ck << KIND_SHIFT;
        return now + cross;
    }
    ir[i * IS + CELL] &= CELL_MASK;
    return best == INF ? INF : now + best;
}
static double predictFull(int i, double now) {
    double cross = crossing(i, now);
    int ck = crossKind;
    found = INF;
    foundP = NONE;
    int packed = ir[i * IS + CELL];
    int col = packed & AXIS_MASK, row = (packed >> AXIS_BITS) & AXIS_MASK;
    if (interior(col, row)) scan(i, now, row * cols + col, around, NO_SHIFT, NO_SHIFT, 9);
    else {
        int m = 0;
        for (int dr = -1; dr <= 1; dr++)
            for (int dc = -1; dc <= 1; dc++) m = visit(col + dc, row + dr, m);
        scan(i, now, 0, visitCell, visitShiftX, visitShiftY, m);
    }
    predictions++;
    return schedule(i, now, found, foundP, cross, ck);
}
static inline double contactTime(int i, int j, double now) {
    int at = i * ST, jt = j * ST;
    double xi = rec[at + X] + rec[at + VX] * (now - rec[at + T]);
    double yi = rec[at + Y] + rec[at + VY] * (now - rec[at + T]);
    double dx = sepX(rec[jt + X] + rec[jt + VX] * (now - rec[jt + T]) - xi);
    double dy = sepY(rec[jt + Y] + rec[jt + VY] * (now - rec[jt + T]) - yi);
    return timeToContact(dx, dy, rec[jt + VX] - rec[at + VX], rec[jt + VY] - rec[at + VY], radius + radius);
}
static double predictAfterCrossing(int i, double now, int k, int col, int row) {
    int bestP = ir[i * IS + PARTNER];
    double cross = crossing(i, now);
    int ck = crossKind;
    double best = INF;
    if (bestP >= 0) {
        if (ir[bestP * IS + COUNT] != ir[i * IS + PCOUNT]) return predictFull(i, now);
        best = contactTime(i, bestP, now);
    }
    found = best;
    foundP = best == INF ? NONE : bestP;
    if (interior(col, row)) scan(i, now, row * cols + col, ahead[k], NO_SHIFT, NO_SHIFT, 3);
    else {
        int dc = k == CROSS_RIGHT ? 1 : (k == CROSS_LEFT ? -1 : 0);
        int dr = k == CROSS_UP ? 1 : (k == CROSS_DOWN ? -1 : 0);
        int m = 0;
        for (int s = -1; s <= 1; s++) m = visit(col + dc + (dc == 0 ? s : 0), row + dr + (dr == 0 ? s : 0), m);
        scan(i, now, 0, visitCell, visitShiftX, visitShiftY, m);
    }
    predictions++;
    return schedule(i, now, found, foundP, cross, ck);
}
static inline void cunlink(int i, int cell) {
    int h = cellHead[cell];
    if (h == i) cellHead[cell] = ir[i * IS + CNEXT];
    else {
        while (ir[h * IS + CNEXT] != i) h = ir[h * IS + CNEXT];
        ir[h * IS + CNEXT] = ir[i * IS + CNEXT];
    }
}
static inline int moveCell(int i, int k) {
    int packed = ir[i * IS + CELL];
    int col = packed & AXIS_MASK, row = (packed >> AXIS_BITS) & AXIS_MASK;
    int old = row * cols + col;
    switch (k) {
    case CROSS_LEFT: if (--col < 0) { col = cols - 1; rec[i * ST + X] += width; } break;
    case CROSS_RIGHT: if (++col == cols) { col = 0; rec[i * ST + X] -= width; } break;
    case CROSS_DOWN: if (--row < 0) { row = rows - 1; rec[i * ST + Y] += height; } break;
    default: if (++row == rows) { row = 0; rec[i * ST + Y] -= height; } break;
    }
    cunlink(i, old);
    int cell = row * cols + col;
    ir[i * IS + CNEXT] = cellHead[cell];
    cellHead[cell] = i;
    ir[i * IS + CELL] = row << AXIS_BITS | col;
    return row << AXIS_BITS | col;
}

/* ---- table ---- */
static int colOf(double x) { int c = (int) (x / cellW); return c < 0 ? 0 : (c >= cols ? cols - 1 : c); }
static int rowOf(double y) { int r = (int) (y / cellH); return r < 0 ? 0 : (r >= rows ? rows - 1 : r); }
static int spread(int v) {
    v &= 0xFFFF;
    v = (v | (v << 8)) & 0x00FF00FF;
    v = (v | (v << 4)) & 0x0F0F0F0F;
    v = (v | (v << 2)) & 0x33333333;
    return (v | (v << 1)) & 0x55555555;
}
static long long cellsAlong(double length, double minCell) {
    double k = floor(length / minCell);
    return k >= 1 ? (long long) fmin(k, 1 << 30) : 1;
}
static int nlz(unsigned v) { return v == 0 ? 32 : __builtin_clz(v); }
static void buildTable(void) {
    double cellFactor = 1.0;
    if (getenv("DILUTE_CELLS")) { /* fast's default cell factor since the cell-factor note: 0.5/phi - 2 in [1, 3] */
        double phi = n * M_PI * radius * radius / (width * height);
        cellFactor = fmax(1, fmin(3, 0.5 / phi - 2));
    }
    double minCell = 2 * radius * cellFactor * (1 + 1e-9);
    long long c = cellsAlong(width, minCell), r = cellsAlong(height, minCell);
    long long cap = 4LL * n > 64 ? 4LL * n : 64;
    while (c * r > cap) {
        double shrink = sqrt((double) c * r / cap) * 1.0001;
        c = (long long) (c / shrink); if (c < 1) c = 1;
        r = (long long) (r / shrink); if (r < 1) r = 1;
    }
    cols = (int) (c < AXIS_MASK ? c : AXIS_MASK);
    rows = (int) (r < AXIS_MASK ? r : AXIS_MASK);
    cellW = width / cols;
    cellH = height / rows;
    if (cols < 4 || rows < 4) { fprintf(stderr, "error: fewer than 4 cells per axis\n"); exit(2); }
    cellHead = malloc(sizeof(int) * cols * rows);
    int a[9] = {-cols - 1, -cols, -cols + 1, -1, 0, 1, cols - 1, cols, cols + 1};
    memcpy(around, a, sizeof a);
    int l[3] = {-cols - 1, -1, cols - 1}, rr[3] = {-cols + 1, 1, cols + 1}, d[3] = {-cols - 1, -cols, -cols + 1},
        u[3] = {cols - 1, cols, cols + 1};
    memcpy(ahead[CROSS_LEFT], l, sizeof l);
    memcpy(ahead[CROSS_RIGHT], rr, sizeof rr);
    memcpy(ahead[CROSS_DOWN], d, sizeof d);
    memcpy(ahead[CROSS_UP], u, sizeof u);
    ir = malloc(sizeof(int) * (size_t) n * IS);
    rec = malloc(sizeof(double) * (size_t) n * ST);
    for (int i = 0; i < cols * rows; i++) cellHead[i] = NIL;
    /* Morton order */
    int shiftC = 32 - nlz(cols - 1) - 16; if (shiftC < 0) shiftC = 0;
    int shiftR = 32 - nlz(rows - 1) - 16; if (shiftR < 0) shiftR = 0;
    int *key = malloc(4 * n), *ids = malloc(4 * n), *ids2 = malloc(4 * n), *key2 = malloc(4 * n);
    int *counts = malloc(4 << 16);
    for (int i = 0; i < n; i++) {
        key[i] = spread((unsigned) colOf(sx[i]) >> shiftC) | (spread((unsigned) rowOf(sy[i]) >> shiftR) << 1);
        ids[i] = i;
    }
    for (int pass = 0; pass < 2; pass++) {
        int shift = 16 * pass;
        memset(counts, 0, 4 << 16);
        for (int i = 0; i < n; i++) counts[((unsigned) key[i] >> shift) & 0xFFFF]++;
        int sum = 0;
        for (int b = 0; b < (1 << 16); b++) { int cnt = counts[b]; counts[b] = sum; sum += cnt; }
        for (int i = 0; i < n; i++) {
            int at = counts[((unsigned) key[i] >> shift) & 0xFFFF]++;
            ids2[at] = ids[i];
            key2[at] = key[i];
        }
        int *t = ids; ids = ids2; ids2 = t;
        t = key; key = key2; key2 = t;
    }
    sceneIds = ids;
    free(key); free(key2); free(ids2); free(counts);
    for (int k = 0; k < n; k++) {
        int o = ids[k], at = k * ST;
        rec[at + X] = sx[o];
        rec[at + Y] = sy[o];
        rec[at + VX] = svx[o];
        rec[at + VY] = svy[o];
        rec[at + T] = 0;
        rec[at + EV] = INF;
    }
    memset(ir, 0, sizeof(int) * (size_t) n * IS);
    for (int k = n - 1; k >= 0; k--) {
        int row = rowOf(rec[k * ST + Y]), col = colOf(rec[k * ST + X]);
        int cell = row * cols + col;
        ir[k * IS + CELL] = row << AXIS_BITS | col;
        ir[k * IS + CNEXT] = cellHead[cell];
        cellHead[cell] = k;
    }
    for (int i = 0; i < n; i++) ir[i * IS + PARTNER] = NONE;
}

/* ---- run ---- */
static double epoch, untilLocal, resyncAt;
static double meanDelay(double now, double fallback) {
    double sum = 0; long long k = 0;
    for (int q = 0; q < n; q++) { double t = rec[q * ST + EV]; if (t != INF) { sum += t - now; k++; } }
    double mean = k > 0 ? sum / k : 1;
    if (k > 0) {
        double cut = 10 * mean;
        sum = 0; k = 0;
        for (int q = 0; q < n; q++) { double t = rec[q * ST + EV]; if (t - now <= cut) { sum += t - now; k++; } }
        mean = k > 0 ? sum / k : mean;
    }
    if (!(mean > 0) || isinf(mean)) mean = fallback;
    return mean;
}
static void replan(double now) {
    double mean = meanDelay(now, untilLocal > 0 && isfinite(untilLocal) ? untilLocal : 1);
    double span = SPAN_MEANS * mean;
    qrebuild(span / buckets, now);
    resyncAt = now + RESYNC_SPANS * span;
}
static void resync(double now) {
    if (now > 0) {
        resyncs++;
        for (int i = 0; i < n; i++) {
            advance(i, now);
            rec[i * ST + T] = 0;
            if (rec[i * ST + EV] != INF) rec[i * ST + EV] = fmax(0, rec[i * ST + EV] - now);
        }
        epoch += now;
        untilLocal = until - epoch;
    }
    replan(0);
}
static void collidePair(int a, int b, double now) {
    advance(a, now);
    advance(b, now);
    int at = a * ST, bt = b * ST;
    double dx = sepX(rec[bt + X] - rec[at + X]);
    double dy = sepY(rec[bt + Y] - rec[at + Y]);
    double e = 1;
    double dist = sqrt(dx * dx + dy * dy);
    double nx = dx / dist, ny = dy / dist;
    double u = (rec[at + VX] - rec[bt + VX]) * nx + (rec[at + VY] - rec[bt + VY]) * ny;
    if (u > 0) {
        double impulse = (1 + e) * u / (invMass + invMass);
        rec[at + VX] -= impulse * invMass * nx;
        rec[at + VY] -= impulse * invMass * ny;
        rec[bt + VX] += impulse * invMass * nx;
        rec[bt + VY] += impulse * invMass * ny;
    }
    ir[a * IS + COUNT]++;
    ir[b * IS + COUNT]++;
    pairCollisions++;
    qinsert(a, predictFull(a, now));
    qremove(b);
    qinsert(b, predictFull(b, now));
}
static void loop(void) {
    untilLocal = until - epoch;
    for (;;) {
        int i = qpeek();
        if (i < 0) return;
        double now = qtime(i);
        if (now > untilLocal) return;
        if (now >= resyncAt) { resync(now); continue; }
        qpollTop();
        events++;
        int other = ir[i * IS + PARTNER];
        int k = (unsigned) ir[i * IS + CELL] >> KIND_SHIFT;
        if (k != HIT) {
            crossings++;
            advance(i, now);
            int packed = moveCell(i, k);
            qinsert(i, predictAfterCrossing(i, now, k, packed & AXIS_MASK, (unsigned) packed >> AXIS_BITS));
        } else if (other >= 0) {
            if (ir[other * IS + COUNT] != ir[i * IS + PCOUNT]) {
                staleEvents++;
                advance(i, now);
                qinsert(i, predictFull(i, now));
            } else collidePair(i, other, now);
        }
    }
}
static double nowSeconds(void) { struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return ts.tv_sec + 1e-9 * ts.tv_nsec; }

int main(int argc, char **argv) {
    if (argc < 2) { fprintf(stderr, "usage: fastc gas.bin [repeats]\n"); return 2; }
    int repeats = argc > 2 ? atoi(argv[2]) : 3;
    int warmups = argc > 3 ? atoi(argv[3]) : 0;
    double rateSum = 0;
    FILE *f = fopen(argv[1], "rb");
    if (!f) { fprintf(stderr, "error: cannot read %s\n", argv[1]); return 2; }
    double hdr[5];
    if (fread(&n, 4, 1, f) != 1 || fread(hdr, 8, 5, f) != 5) { fprintf(stderr, "error: short file\n"); return 2; }
    width = hdr[0]; height = hdr[1]; radius = hdr[2]; invMass = hdr[3]; until = hdr[4];
    sx = malloc(8 * n); sy = malloc(8 * n); svx = malloc(8 * n); svy = malloc(8 * n);
    if (fread(sx, 8, n, f) != (size_t) n || fread(sy, 8, n, f) != (size_t) n || fread(svx, 8, n, f) != (size_t) n
        || fread(svy, 8, n, f) != (size_t) n) { fprintf(stderr, "error: short file\n"); return 2; }
    fclose(f);
    for (int r = -warmups; r < repeats; r++) {
        double t0 = nowSeconds();
        epoch = 0; predictions = events = pairCollisions = crossings = staleEvents = resyncs = 0;
        buildTable();
        double t1 = nowSeconds();
        buckets = 1; { int h = n / 2 - 1 > 64 ? n / 2 - 1 : 64; while (buckets * 2 <= h) buckets *= 2; buckets <<= 1; }
        qmask = buckets - 1;
        qhead = malloc(sizeof(int) * buckets);
        heapCap = 256; heap = malloc(sizeof(int) * heapCap);
        untilLocal = until;
        for (int i = 0; i < n; i++) rec[i * ST + EV] = predictFull(i, 0);
        replan(0);
        double t2 = nowSeconds();
        loop();
        double t3 = nowSeconds();
        /* final state at until, in scene order (not timed separately: GasBench times the whole run) */
        double cx = 0, cv = 0;
        double *fx = malloc(8 * n), *fy = malloc(8 * n), *fvx = malloc(8 * n), *fvy = malloc(8 * n);
        for (int k = 0; k < n; k++) {
            advance(k, untilLocal);
            int o = sceneIds[k];
            double x = rec[k * ST + X], y = rec[k * ST + Y];
            fx[o] = x - width * floor(x / width);
            fy[o] = y - height * floor(y / height);
            fvx[o] = rec[k * ST + VX];
            fvy[o] = rec[k * ST + VY];
        }
        double s = nowSeconds() - t0;
        if (getenv("PHASES")) fprintf(stderr, "phases: table %.3f first predictions %.3f loop %.3f final %.3f s\n", t1 - t0, t2 - t1, t3 - t2, t0 + s - t3);
        for (int i = 0; i < n; i++) { cx += fx[i] + fy[i]; cv += fvx[i] * fvx[i] + fvy[i] * fvy[i]; }
        printf("c port: collisions %lld events %lld crossings %lld stale %lld in %.3f s, %.4f M coll/s; sum v2 %.10f sum x+y %.10f\n",
               pairCollisions, events, crossings, staleEvents, s, pairCollisions / s / 1e6, cv, cx);
        if (r >= 0) rateSum += pairCollisions / s;
        free(fx); free(fy); free(fvx); free(fvy); free(rec); free(ir); free(cellHead); free(sceneIds); free(qhead); free(heap);
    }
    printf("c,%d,%.0f,%d timed runs after %d warm-ups\n", n, rateSum / repeats, repeats, warmups);
    return 0;
}
