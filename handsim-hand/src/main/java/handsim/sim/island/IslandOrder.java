package handsim.sim.island;

import java.util.Arrays;

/**
 * The step's islands and the order of their joints, found as ODE finds them: bodies taken in
 * the engine's body list order (the most recently created first), each untagged one starting an
 * island that grows depth first, every body's joints visited in the order of its joint list (the
 * most recently attached first: this step's contacts, newest first, before the articulation's
 * joints). The rows are assembled in this order, and the solver sweeps them in it, so a step
 * solves the same equations in the same sequence as ode4j's quickStep.
 *
 * <p>A joint is encoded as its articulation index, a contact k as {@code -(k + 1)}.
 */
final class IslandOrder {

    private final int bodyCount;
    /** Each body's articulation joints, most recently attached first. */
    private final int[] adjacencyStart;
    private final int[] adjacency;
    private final int[] listOrder;

    private final boolean[] bodyTagged;
    private boolean[] jointTagged;
    private boolean[] contactTagged = new boolean[16];
    private final int[] stack;
    /** The joints of every island, one after another. */
    int[] joints;
    int jointCount;
    /** Island i holds joints [islandStart[i], islandStart[i + 1]). */
    int[] islandStart;
    int islandCount;

    /**
     * @param listOrder the bodies in the engine's body list order (the most recently created first)
     */
    IslandOrder(Articulation a, int bodyCount, int[] listOrder) {
        this.bodyCount = bodyCount;
        this.listOrder = listOrder.clone();
        int[] degree = new int[bodyCount];
        for (int j = 0; j < a.count; j++) {
            degree[a.body1[j]]++;
            degree[a.body2[j]]++;
        }
        adjacencyStart = new int[bodyCount + 1];
        for (int b = 0; b < bodyCount; b++) {
            adjacencyStart[b + 1] = adjacencyStart[b] + degree[b];
        }
        adjacency = new int[adjacencyStart[bodyCount]];
        int[] fill = adjacencyStart.clone();
        // attached in creation order, each at the head of both bodies' lists
        for (int j = a.count - 1; j >= 0; j--) {
            adjacency[fill[a.body1[j]]++] = j;
            adjacency[fill[a.body2[j]]++] = j;
        }
        bodyTagged = new boolean[bodyCount];
        jointTagged = new boolean[a.count];
        stack = new int[bodyCount];
        joints = new int[a.count + 16];
        islandStart = new int[bodyCount + 1];
    }

    /** Finds the islands of the active bodies joined by the articulation and this step's contacts. */
    void build(Articulation a, ContactPoints c, boolean[] active) {
        Arrays.fill(bodyTagged, false);
        Arrays.fill(jointTagged, false);
        if (contactTagged.length < c.count) {
            contactTagged = new boolean[Math.max(c.count, 2 * contactTagged.length)];
        }
        Arrays.fill(contactTagged, 0, c.count, false);
        if (joints.length < a.count + c.count) {
            joints = new int[Math.max(a.count + c.count, 2 * joints.length)];
        }
        jointCount = 0;
        islandCount = 0;
        for (int start : listOrder) {
            if (!active[start] || bodyTagged[start]) {
                continue;
            }
            islandStart[islandCount++] = jointCount;
            bodyTagged[start] = true;
            int depth = 0;
            int b = start;
            while (true) {
                depth = visit(a, c, b, active, depth);
                if (depth == 0) {
                    break;
                }
                b = stack[--depth];
            }
        }
        islandStart[islandCount] = jointCount;
    }

    /** Tags body {@code b}'s untagged joints in list order, pushing the bodies they reach; returns the stack depth. */
    private int visit(Articulation a, ContactPoints c, int b, boolean[] active, int depth) {
        for (int k = c.count - 1; k >= 0; k--) {
            if (contactTagged[k] || (c.body1[k] != b && c.body2[k] != b)) {
                continue;
            }
            contactTagged[k] = true;
            joints[jointCount++] = -(k + 1);
            depth = push(c.body1[k] == b ? c.body2[k] : c.body1[k], active, depth);
        }
        for (int i = adjacencyStart[b]; i < adjacencyStart[b + 1]; i++) {
            int j = adjacency[i];
            if (jointTagged[j]) {
                continue;
            }
            jointTagged[j] = true;
            joints[jointCount++] = j;
            depth = push(a.body1[j] == b ? a.body2[j] : a.body1[j], active, depth);
        }
        return depth;
    }

    private int push(int other, boolean[] active, int depth) {
        if (other >= 0 && other < bodyCount && active[other] && !bodyTagged[other]) {
            bodyTagged[other] = true;
            stack[depth++] = other;
        }
        return depth;
    }
}
