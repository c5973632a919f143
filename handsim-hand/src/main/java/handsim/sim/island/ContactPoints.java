package handsim.sim.island;

import java.util.Arrays;

/**
 * The contact points of one step, in the order the collision generated them: between body 1
 * and body 2 (-1: static geometry), a point (m, world), the unit normal along which body 1 is
 * pushed out of body 2, the penetration depth (m), the contact's ERP and CFM (the compliant
 * contact of sec. 4.1 as ODE's soft ERP/CFM) and its Coulomb friction coefficient. Cleared at
 * the end of every step; grows when a step has more contacts than any before.
 */
public final class ContactPoints {

    int count;
    int[] body1 = new int[16];
    int[] body2 = new int[16];
    /** Point (3), normal (3), depth, erp, cfm, mu per contact. */
    double[] data = new double[GEOMETRY * 16];

    static final int POINT = 0, NORMAL = 3, DEPTH = 6, ERP = 7, CFM = 8, MU = 9, GEOMETRY = 10;

    /** Adds a contact; see the class comment for the meaning and units of each number. */
    public void add(int b1, int b2, double px, double py, double pz, double nx, double ny, double nz, double depth,
            double erp, double cfm, double mu) {
        if (count == body1.length) {
            int n = 2 * count;
            body1 = Arrays.copyOf(body1, n);
            body2 = Arrays.copyOf(body2, n);
            data = Arrays.copyOf(data, GEOMETRY * n);
        }
        int k = count++;
        body1[k] = b1;
        body2[k] = b2;
        int o = GEOMETRY * k;
        data[o + POINT] = px;
        data[o + POINT + 1] = py;
        data[o + POINT + 2] = pz;
        data[o + NORMAL] = nx;
        data[o + NORMAL + 1] = ny;
        data[o + NORMAL + 2] = nz;
        data[o + DEPTH] = depth;
        data[o + ERP] = erp;
        data[o + CFM] = cfm;
        data[o + MU] = mu;
    }

    public int count() {
        return count;
    }

    public void clear() {
        count = 0;
    }
}
