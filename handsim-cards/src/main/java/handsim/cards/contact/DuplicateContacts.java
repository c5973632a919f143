package handsim.cards.contact;

import handsim.cards.geom.DistanceType;
import java.util.Arrays;

/**
 * The merge of a contact set's repeats: its active contacts sorted by key (the key encodes kind
 * and nodes, so the order is deterministic), and the contacts of one key made one whose
 * multiplicity is their sum (the candidate pairs that reduce to one contact, as a vertex against
 * the two faces of an edge, count its barrier that often).
 */
final class DuplicateContacts {

    private DuplicateContacts() {
    }

    /** Sorts {@code set}'s active contacts by key and merges the repeats. */
    static void merge(ContactSet set) {
        Integer[] idx = new Integer[set.count];
        for (int i = 0; i < set.count; i++) {
            idx[i] = i;
        }
        Arrays.sort(idx, (a, b) -> Long.compare(set.keys[a], set.keys[b]));
        int[] k2 = new int[set.count];
        int[] n2 = new int[4 * set.count];
        double[] xi2 = new double[set.count];
        double[] eps2 = new double[set.count];
        DistanceType[] m2 = new DistanceType[set.count];
        int[] mult2 = new int[set.count];
        long[] key2 = new long[set.count];
        int out = 0;
        for (int i = 0; i < set.count; i++) {
            int s = idx[i];
            if (out > 0 && key2[out - 1] == set.keys[s]) {
                mult2[out - 1] += set.multiplicity[s];
                continue;
            }
            k2[out] = set.kind[s];
            System.arraycopy(set.nodes, 4 * s, n2, 4 * out, 4);
            xi2[out] = set.xi[s];
            eps2[out] = set.epsX[s];
            m2[out] = set.mollified[s];
            mult2[out] = set.multiplicity[s];
            key2[out] = set.keys[s];
            out++;
        }
        System.arraycopy(k2, 0, set.kind, 0, out);
        System.arraycopy(n2, 0, set.nodes, 0, 4 * out);
        System.arraycopy(xi2, 0, set.xi, 0, out);
        System.arraycopy(eps2, 0, set.epsX, 0, out);
        System.arraycopy(m2, 0, set.mollified, 0, out);
        System.arraycopy(mult2, 0, set.multiplicity, 0, out);
        System.arraycopy(key2, 0, set.keys, 0, out);
        set.count = out;
    }
}
