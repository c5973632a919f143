package handsim.cards.contact;

import java.util.Arrays;

/**
 * A uniform-grid spatial hash over axis-aligned boxes: each box is entered in every cell it
 * overlaps, as one sorted array of (cell, id) keys, and a query visits the ids stored in the
 * cells its box overlaps. Sorting makes the visiting order, and so the whole simulation,
 * deterministic. Cells are counted from the lower corner of the boxes entered.
 */
final class SpatialHash {

    private static final int BITS = 12;
    private static final int ID_BITS = 64 - 1 - 3 * BITS;

    private final double cell;
    /** The most (cell, id) entries one build may make: a memory budget (8 bytes each, and the cell table's 32). */
    private long maxEntries = Long.MAX_VALUE;
    private long[] entries = new long[0];
    private int size;
    private double ox;
    private double oy;
    private double oz;
    /** open-addressing table from a cell to its run of entries: cell key, first entry, end */
    private long[] tableKey = new long[0];
    private int[] tableFirst = new int[0];
    private int[] tableEnd = new int[0];
    private int tableMask;
    /** visit stamps to report each id once per query */
    private int[] stamp = new int[0];
    private int query;

    SpatialHash(double cellSize) {
        this.cell = cellSize;
    }

    /** Sets the most (cell, id) entries a build may make; a build past it throws {@link BudgetExceeded}. */
    void limit(long entries) {
        this.maxEntries = entries;
    }

    /** Enters {@code count} boxes (6 numbers each: min xyz, max xyz). */
    void build(double[] boxes, int count) {
        if (count >= (1 << ID_BITS)) {
            throw new IllegalArgumentException("too many boxes for the hash: " + count);
        }
        ox = Double.POSITIVE_INFINITY;
        oy = Double.POSITIVE_INFINITY;
        oz = Double.POSITIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            ox = Math.min(ox, boxes[6 * i]);
            oy = Math.min(oy, boxes[6 * i + 1]);
            oz = Math.min(oz, boxes[6 * i + 2]);
        }
        long needed = 0;
        for (int i = 0; i < count; i++) {
            // counted before anything is allocated: a box swept far (a bone moved absurdly fast) spans billions of cells
            needed += (long) (cellOf(boxes[6 * i + 3], ox) - cellOf(boxes[6 * i], ox) + 1)
                    * (cellOf(boxes[6 * i + 4], oy) - cellOf(boxes[6 * i + 1], oy) + 1)
                    * (cellOf(boxes[6 * i + 5], oz) - cellOf(boxes[6 * i + 2], oz) + 1);
            if (needed > maxEntries || needed > Integer.MAX_VALUE - 8) {
                throw new BudgetExceeded("the spatial hash needs more than " + Math.min(maxEntries, Integer.MAX_VALUE - 8L)
                        + " cell entries (configs/cards/budget.json maxHashEntries): the bodies' boxes span too much space");
            }
        }
        size = 0;
        for (int i = 0; i < count; i++) {
            int x0 = cellOf(boxes[6 * i], ox);
            int y0 = cellOf(boxes[6 * i + 1], oy);
            int z0 = cellOf(boxes[6 * i + 2], oz);
            int x1 = cellOf(boxes[6 * i + 3], ox);
            int y1 = cellOf(boxes[6 * i + 4], oy);
            int z1 = cellOf(boxes[6 * i + 5], oz);
            for (int x = x0; x <= x1; x++) {
                for (int y = y0; y <= y1; y++) {
                    for (int z = z0; z <= z1; z++) {
                        if (size == entries.length) {
                            entries = Arrays.copyOf(entries, Math.max(1024, 2 * size));
                        }
                        entries[size++] = (cellKey(x, y, z) << ID_BITS) | i;
                    }
                }
            }
        }
        Arrays.sort(entries, 0, size);
        index();
        if (stamp.length < count) {
            stamp = new int[count];
            query = 0;
        }
    }

    /** Fills the cell table from the sorted entries. */
    private void index() {
        int cap = Integer.highestOneBit(Math.max(16, 4 * size) - 1) << 1;
        if (tableKey.length != cap) {
            tableKey = new long[cap];
            tableFirst = new int[cap];
            tableEnd = new int[cap];
        }
        Arrays.fill(tableKey, -1L);
        tableMask = cap - 1;
        int at = 0;
        while (at < size) {
            long cellKey = entries[at] >>> ID_BITS;
            int end = at + 1;
            while (end < size && (entries[end] >>> ID_BITS) == cellKey) {
                end++;
            }
            int slot = slot(cellKey);
            while (tableKey[slot] != -1L) {
                slot = (slot + 1) & tableMask;
            }
            tableKey[slot] = cellKey;
            tableFirst[slot] = at;
            tableEnd[slot] = end;
            at = end;
        }
    }

    private int slot(long cellKey) {
        long h = cellKey * 0x9E3779B97F4A7C15L;
        return (int) (h >>> 40) & tableMask;
    }

    private int cellOf(double v, double origin) {
        int c = (int) Math.floor((v - origin) / cell);
        return Math.max(0, Math.min((1 << BITS) - 1, c));
    }

    private static long cellKey(int x, int y, int z) {
        return ((long) x << (2 * BITS)) | ((long) y << BITS) | z;
    }

    interface Visitor {
        void visit(int id);
    }

    /** Visits, once each, the ids whose cells the box overlaps (a superset of overlapping boxes). */
    void query(double minX, double minY, double minZ, double maxX, double maxY, double maxZ, Visitor visitor) {
        if (size == 0) {
            return;
        }
        query++;
        if (query == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            query = 1;
        }
        int x0 = cellOf(minX, ox);
        int y0 = cellOf(minY, oy);
        int z0 = cellOf(minZ, oz);
        int x1 = cellOf(maxX, ox);
        int y1 = cellOf(maxY, oy);
        int z1 = cellOf(maxZ, oz);
        long idMask = (1L << ID_BITS) - 1;
        for (int x = x0; x <= x1; x++) {
            for (int y = y0; y <= y1; y++) {
                for (int z = z0; z <= z1; z++) {
                    long key = cellKey(x, y, z);
                    int slot = slot(key);
                    while (tableKey[slot] != -1L && tableKey[slot] != key) {
                        slot = (slot + 1) & tableMask;
                    }
                    if (tableKey[slot] == -1L) {
                        continue;
                    }
                    for (int at = tableFirst[slot]; at < tableEnd[slot]; at++) {
                        int id = (int) (entries[at] & idMask);
                        if (stamp[id] != query) {
                            stamp[id] = query;
                            visitor.visit(id);
                        }
                    }
                }
            }
        }
    }
}
