package handsim.cards.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.cards.IpcOracle;
import handsim.cards.contact.Barrier;
import handsim.cards.contact.FrictionMollifier;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The contact kernels against values computed by the IPC Toolkit 1.6.1 (ipc-oracle.json). CARDS.md
 * fixes the tolerances: distances, derivatives, barrier and friction to 1e-9 relative; additive CCD
 * the same hit/no-hit and a time of impact never later than the reference and within 20 % of it.
 * "Relative" is taken per array: every entry within 1e-9 of the array's largest magnitude.
 */
@Tag("fast")
class IpcOracleTest {

    private static final double REL = 1e-9;

    static void assertClose(double expected, double actual, String what) {
        assertTrue(Math.abs(expected - actual) <= REL * Math.abs(expected) + 1e-300,
                what + ": expected " + expected + ", got " + actual);
    }

    static void assertArrayClose(double[] expected, double[] actual, String what) {
        assertEquals(expected.length, actual.length, what + " length");
        double scale = 0;
        for (double e : expected) {
            scale = Math.max(scale, Math.abs(e));
        }
        for (int i = 0; i < expected.length; i++) {
            assertTrue(Math.abs(expected[i] - actual[i]) <= REL * scale + 1e-300,
                    what + "[" + i + "]: expected " + expected[i] + ", got " + actual[i] + " (scale " + scale + ")");
        }
    }

    /** A stencil kernel: squared distance, gradient and Hessian of the 12 coordinates. */
    private interface Kernel {
        double d2(double[] x, double[] g, double[] h);
    }

    private static void checkStencilCases(String name, String[] fields, java.util.function.Function<double[], DistanceType> type, Kernel kernel) {
        int n = 0;
        for (JsonNode c : IpcOracle.cases(name)) {
            double[] x = IpcOracle.stack(c, fields);
            assertEquals(c.get("type").asText(), type.apply(x).ipcName(), "type of " + name + " case " + n);
            double[] g = new double[12];
            double[] h = new double[144];
            double d2 = kernel.d2(x, g, h);
            assertClose(c.get("d2").asDouble(), d2, "d2 of " + name + " case " + n);
            assertArrayClose(IpcOracle.numbers(c.get("grad")), g, "grad of " + name + " case " + n);
            assertArrayClose(IpcOracle.numbers(c.get("hess")), h, "hess of " + name + " case " + n);
            n++;
        }
        assertEquals(60, n);
    }

    @Test
    void pointTriangleDistancesTypesAndDerivatives() {
        checkStencilCases("point_triangle", new String[] {"p", "t0", "t1", "t2"}, DistanceTypes::pointTriangle, Distances::pointTriangle);
    }

    @Test
    void edgeEdgeDistancesTypesAndDerivatives() {
        checkStencilCases("edge_edge", new String[] {"ea0", "ea1", "eb0", "eb1"}, DistanceTypes::edgeEdge, Distances::edgeEdge);
    }

    @Test
    void pointEdgeDistancesAndGradients() {
        for (JsonNode c : IpcOracle.cases("point_edge")) {
            double[] x = IpcOracle.stack(c, "p", "e0", "e1");
            double[] g = new double[9];
            assertClose(c.get("d2").asDouble(), Distances.pointEdge(x, g, null), "d2");
            assertArrayClose(IpcOracle.numbers(c.get("grad")), g, "grad");
        }
    }

    @Test
    void logBarrierAndItsDerivatives() {
        for (JsonNode c : IpcOracle.cases("barrier")) {
            double d = c.get("d").asDouble();
            double dhat = c.get("dhat").asDouble();
            assertClose(c.get("b").asDouble(), Barrier.value(d, dhat), "b(" + d + ")");
            assertClose(c.get("db").asDouble(), Barrier.slope(d, dhat), "b'(" + d + ")");
            assertClose(c.get("d2b").asDouble(), Barrier.curvature(d, dhat), "b''(" + d + ")");
        }
    }

    @Test
    void frictionMollifiers() {
        for (JsonNode c : IpcOracle.cases("friction_f0_f1")) {
            double y = c.get("y").asDouble();
            double eps = c.get("eps_v").asDouble();
            assertClose(c.get("f0").asDouble(), FrictionMollifier.f0(y, eps), "f0");
            assertClose(c.get("f1").asDouble(), FrictionMollifier.f1(y, eps), "f1");
            assertClose(c.get("f1_over_x").asDouble(), FrictionMollifier.f1OverY(y, eps), "f1/y");
        }
    }

    @Test
    void dihedralAngleAndGradient() {
        DihedralAngle kernel = new DihedralAngle();
        for (JsonNode c : IpcOracle.cases("dihedral_angle")) {
            double[] x = IpcOracle.numbers(c.get("x"));
            assertClose(c.get("angle").asDouble(), DihedralAngle.angle(x), "angle");
            Jet theta = kernel.evaluate(x);
            assertClose(c.get("angle").asDouble(), theta.v, "angle (jet)");
            assertArrayClose(IpcOracle.numbers(c.get("grad")), theta.g, "grad");
        }
    }

    @Test
    void edgeEdgeMollifier() {
        for (JsonNode c : IpcOracle.cases("edge_edge_mollifier")) {
            double[] x = IpcOracle.stack(c, "ea0", "ea1", "eb0", "eb1");
            double eps = c.get("eps_x").asDouble();
            assertClose(eps, EdgeEdgeMollifier.threshold(IpcOracle.numbers(c.get("rest"))), "eps_x");
            double[] g = new double[12];
            assertClose(c.get("m").asDouble(), EdgeEdgeMollifier.evaluate(x, eps, g, null), "m");
            assertArrayClose(IpcOracle.numbers(c.get("grad")), g, "grad");
        }
    }

    @Test
    void additiveCcdHitsAsTheReferenceAndNeverLater() {
        for (String kind : new String[] {"accd_point_triangle", "accd_edge_edge"}) {
            int n = 0;
            for (JsonNode c : IpcOracle.cases(kind)) {
                double[] x0;
                double[] x1;
                if (kind.equals("accd_point_triangle")) {
                    x0 = concat(IpcOracle.numbers(c.get("p_t0")), IpcOracle.numbers(c.get("t_t0")));
                    x1 = concat(IpcOracle.numbers(c.get("p_t1")), IpcOracle.numbers(c.get("t_t1")));
                } else {
                    x0 = concat(IpcOracle.numbers(c.get("ea_t0")), IpcOracle.numbers(c.get("eb_t0")));
                    x1 = concat(IpcOracle.numbers(c.get("ea_t1")), IpcOracle.numbers(c.get("eb_t1")));
                }
                double dmin = c.get("min_distance").asDouble();
                double eta = c.get("conservative_rescaling").asDouble();
                double toi = kind.equals("accd_point_triangle")
                        ? AdditiveCcd.pointTriangle(x0, x1, dmin, eta, 1.0)
                        : AdditiveCcd.edgeEdge(x0, x1, dmin, eta, 1.0);
                boolean hit = toi <= 1.0;
                String what = kind + " case " + n;
                assertEquals(c.get("hit").asBoolean(), hit, what + " hit (toi " + toi + ")");
                if (hit) {
                    double ref = c.get("toi").asDouble();
                    assertTrue(toi <= ref, what + ": toi " + toi + " later than the reference " + ref);
                    assertTrue(toi >= 0.8 * ref, what + ": toi " + toi + " below 80 % of the reference " + ref);
                }
                n++;
            }
        }
    }

    private static double[] concat(double[] a, double[] b) {
        double[] out = new double[a.length + b.length];
        System.arraycopy(a, 0, out, 0, a.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
