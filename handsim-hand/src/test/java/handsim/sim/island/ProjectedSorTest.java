package handsim.sim.island;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The sweep leaves out the terms a joint's rows declare as zeros (their shapes); that must give
 * the dense sweep's bits, so that no result depends on it (ProjectedSor's class comment, and
 * docs/design.md: "the shorter sums give the dense sums' bits").
 */
@Tag("fast")
class ProjectedSorTest {

    private static final double H = 2e-4, SOR = 1.3;
    private static final int ITERATIONS = 10; // 8 swept block by block, then 2 shuffled

    @Test
    void declaredZerosChangeNoBitOfTheSolution() {
        for (long seed = 1; seed <= 50; seed++) {
            double[] withShapes = solve(seed, true);
            double[] dense = solve(seed, false);
            for (int i = 0; i < dense.length; i++) {
                // a zero's sign is the only freedom: 0.0 == -0.0
                double x = dense[i], y = withShapes[i];
                assertEquals(x == 0 ? 0 : Double.doubleToRawLongBits(x), y == 0 ? 0 : Double.doubleToRawLongBits(y),
                        "seed " + seed + " fc[" + i + "]: " + y + " against the dense " + x);
            }
        }
    }

    /**
     * A chain of four bodies, each pair joined by a ball's three anchor rows and 0-2 rows without a
     * linear part (some bounded, as stops), a contact of the last body with the world and one with
     * the first, with friction: solved from random velocities, forces and Jacobians, the joints'
     * rows declaring their shapes or all declared dense. Returns fc, M^-1 J^T of the impulses found.
     */
    private static double[] solve(long seed, boolean declareShapes) {
        SplittableRandom rng = new SplittableRandom(seed);
        int n = 4;
        RigidBodies bodies = new RigidBodies(n);
        for (int i = 0; i < n; i++) {
            double[] inertia = new double[9];
            double a = rng.nextDouble(0.5, 2), b = rng.nextDouble(0.5, 2), c = rng.nextDouble(0.5, 2);
            double p = rng.nextDouble(-0.2, 0.2), q = rng.nextDouble(-0.2, 0.2), r = rng.nextDouble(-0.2, 0.2);
            // diagonally dominant, so positive definite; not diagonal, so M^-1 J^T fills every term
            double[] m = {a, p, q, p, b, r, q, r, c};
            for (int k = 0; k < 9; k++) {
                inertia[k] = 1e-4 * m[k];
            }
            bodies.setMass(i, rng.nextDouble(0.01, 1), inertia);
            for (int k = 0; k < 3; k++) {
                bodies.velocity[3 * i + k] = rng.nextDouble(-1, 1);
                bodies.angularVelocity[3 * i + k] = rng.nextDouble(-5, 5);
                bodies.torque[3 * i + k] = rng.nextDouble(-1e-3, 1e-3);
            }
        }
        bodies.prepare(H, 0, -9.81, 0);
        ConstraintRows rows = new ConstraintRows(16);
        for (int j = 0; j + 1 < n; j++) {
            for (int axis = 0; axis < 3; axis++) {
                int o = rows.add(j, j + 1, 1e-5, declareShapes ? ConstraintRows.ANCHOR_X + axis : ConstraintRows.DENSE);
                rows.data[o + ConstraintRows.J1 + axis] = 1;
                rows.data[o + ConstraintRows.J2 + axis] = -1;
                for (int k = 3; k < 6; k++) {
                    if (k != 3 + axis) {
                        rows.data[o + ConstraintRows.J1 + k] = rng.nextDouble(-0.05, 0.05);
                        rows.data[o + ConstraintRows.J2 + k] = rng.nextDouble(-0.05, 0.05);
                    }
                }
                rows.data[o + ConstraintRows.RHS] = rng.nextDouble(-1e-3, 1e-3);
            }
            for (int r = rng.nextInt(3); r > 0; r--) {
                int o = rows.add(j, j + 1, 1e-5, declareShapes ? ConstraintRows.ANGULAR : ConstraintRows.DENSE);
                for (int k = 3; k < 6; k++) {
                    double v = rng.nextDouble(-1, 1);
                    rows.data[o + ConstraintRows.J1 + k] = v;
                    rows.data[o + ConstraintRows.J2 + k] = -v;
                }
                rows.data[o + ConstraintRows.RHS] = rng.nextDouble(-1e-2, 1e-2);
                if (rng.nextBoolean()) {
                    rows.data[o + ConstraintRows.LO] = 0; // a stop: pushes one way only
                }
            }
        }
        contact(rows, rng, n - 1, -1);
        contact(rows, rng, 0, n - 1);
        ProjectedSor solver = new ProjectedSor(n);
        solver.prepare(bodies, H);
        ShuffleRandom random = new ShuffleRandom();
        random.setSeed(seed);
        solver.solve(rows, 0, rows.count, bodies, H, ITERATIONS, SOR, random);
        assertTrue(rows.count >= 3 * (n - 1) + 6, "rows " + rows.count);
        return solver.fc.clone();
    }

    /** A dense normal row of bodies b1, b2 (-1: the world) and its two friction rows. */
    private static void contact(ConstraintRows rows, SplittableRandom rng, int b1, int b2) {
        int normal = rows.count;
        for (int r = 0; r < 3; r++) {
            int o = rows.add(b1, b2, 1e-5);
            for (int k = 0; k < 6; k++) {
                rows.data[o + ConstraintRows.J1 + k] = rng.nextDouble(-1, 1);
                rows.data[o + ConstraintRows.J2 + k] = b2 < 0 ? 0 : rng.nextDouble(-1, 1);
            }
            rows.data[o + ConstraintRows.RHS] = rng.nextDouble(0, 1e-2);
            if (r == 0) {
                rows.data[o + ConstraintRows.LO] = 0;
            } else {
                rows.data[o + ConstraintRows.LO] = -0.8;
                rows.data[o + ConstraintRows.HI] = 0.8;
                rows.findex[rows.count - 1] = normal;
            }
        }
    }
}
