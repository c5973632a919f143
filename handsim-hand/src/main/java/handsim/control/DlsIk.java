package handsim.control;

import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Dense;
import handsim.math.Vec3;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.Site;
import java.util.ArrayList;
import java.util.List;

/**
 * Damped least squares IK for the palm site over the DOFs of its chain (shoulder, elbow,
 * wrist), eq. (2): {@code dq = J^T (J J^T + lambda^2 I)^-1 de}, with the position and
 * orientation rows weighted differently. Joint limits are respected by clamping: a DOF pushed
 * against its limit is frozen (its Jacobian column removed) and the step recomputed.
 */
public final class DlsIk {

    /** Remaining error after a solve. */
    public record Residual(double position, double rotation) {
    }

    private final Kinematics kin;
    private final Site site;
    private final int[] dofs;
    private final IkConfig config;
    private final double[] jac;
    private final double[] jjt = new double[36];
    private final double[] rhs = new double[6];
    private final boolean[] frozen;

    public DlsIk(Kinematics kin, Site site, IkConfig config) {
        this.kin = kin;
        this.site = site;
        this.config = config;
        this.dofs = chainDofs(kin.model(), site.body());
        this.jac = new double[6 * dofs.length];
        this.frozen = new boolean[dofs.length];
    }

    /** The DOFs from the root to the site's body (for the palm: shoulder, elbow, wrist). */
    static int[] chainDofs(HandModel m, int body) {
        List<Integer> out = new ArrayList<>();
        for (Joint j : m.chainTo(body)) {
            for (int s = 0; s < j.dofCount(); s++) {
                out.add(j.firstDof() + s);
            }
        }
        return out.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The DOFs this IK moves. */
    public int[] dofs() {
        return dofs.clone();
    }

    /**
     * Moves the chain DOFs of {@code q} (a full DOF vector, changed in place) toward placing the
     * site at {@code target}, running the configured number of iterations.
     */
    public Residual solve(double[] q, Frame target) {
        return solve(q, target, config.iterations());
    }

    public Residual solve(double[] q, Frame target, int iterations) {
        HandModel m = kin.model();
        for (int it = 0; it < iterations; it++) {
            Frame now = kin.siteFrame(site, q);
            Vec3 ep = clampNorm(target.origin().minus(now.origin()), config.maxPositionStep());
            Vec3 eo = clampNorm(target.rotation().mul(now.rotation().conjugate()).toRotationVector(),
                    config.maxRotationStep());
            double wp = config.positionWeight(), wo = config.orientationWeight();
            double[] e = {wp * ep.x(), wp * ep.y(), wp * ep.z(), wo * eo.x(), wo * eo.y(), wo * eo.z()};
            weightedJacobian(q);
            int n = dofs.length;
            java.util.Arrays.fill(frozen, false);
            // at most one pass per DOF: freeze DOFs the step pushes beyond their limits
            for (int pass = 0; pass <= n; pass++) {
                double[] dq = step(e, n);
                boolean again = false;
                for (int c = 0; c < n; c++) {
                    Dof d = m.dofs().get(dofs[c]);
                    double next = q[dofs[c]] + dq[c];
                    if (!frozen[c] && (next > d.upper() || next < d.lower())
                            && (q[dofs[c]] >= d.upper() - 1e-9 || q[dofs[c]] <= d.lower() + 1e-9)) {
                        frozen[c] = true;
                        again = true;
                    }
                }
                if (!again) {
                    for (int c = 0; c < n; c++) {
                        q[dofs[c]] = m.dofs().get(dofs[c]).clamp(q[dofs[c]] + dq[c]);
                    }
                    break;
                }
            }
        }
        Frame end = kin.siteFrame(site, q);
        return new Residual(end.origin().distance(target.origin()), end.rotation().angleTo(target.rotation()));
    }

    /**
     * One step of the chain DOFs of {@code q} toward {@code posture} (radians, {@link #dofs} order)
     * that leaves the site where it is to first order ({@link ArmRest}): {@code v = gain (posture -
     * q)} less its part the site would feel, {@code dq = v - J+ J v}, with {@code J+} the damped
     * inverse of eq. (2) and the same row weights. The damping lets a little of {@code v} through,
     * and a DOF is clamped to its limits; the next {@link #solve} takes the site back.
     */
    public void pullNullSpace(double[] q, double[] posture, double gain) {
        int n = dofs.length;
        if (posture.length != n) {
            throw new IllegalArgumentException("a posture for the " + n + " DOFs of the chain, got " + posture.length);
        }
        weightedJacobian(q);
        java.util.Arrays.fill(frozen, false);
        double[] v = new double[n];
        for (int c = 0; c < n; c++) {
            v[c] = gain * (posture[c] - q[dofs[c]]);
        }
        double[] felt = new double[6];
        for (int r = 0; r < 6; r++) {
            for (int c = 0; c < n; c++) {
                felt[r] += jac[r * n + c] * v[c];
            }
        }
        double[] back = step(felt, n);
        HandModel m = kin.model();
        for (int c = 0; c < n; c++) {
            q[dofs[c]] = m.dofs().get(dofs[c]).clamp(q[dofs[c]] + v[c] - back[c]);
        }
    }

    /** The site Jacobian at {@code q} over the chain, its position rows times positionWeight, its orientation rows times orientationWeight. */
    private void weightedJacobian(double[] q) {
        kin.siteJacobian(site, q, dofs, jac);
        int n = dofs.length;
        double wp = config.positionWeight(), wo = config.orientationWeight();
        for (int c = 0; c < n; c++) {
            for (int r = 0; r < 6; r++) {
                jac[r * n + c] *= r < 3 ? wp : wo;
            }
        }
    }

    /** eq. (2) with frozen columns removed: dq = J^T (J J^T + lambda^2 I)^-1 e. */
    private double[] step(double[] e, int n) {
        double lambda2 = config.damping() * config.damping();
        for (int r = 0; r < 6; r++) {
            for (int s = 0; s < 6; s++) {
                double sum = r == s ? lambda2 : 0;
                for (int c = 0; c < n; c++) {
                    if (!frozen[c]) {
                        sum += jac[r * n + c] * jac[s * n + c];
                    }
                }
                jjt[r * 6 + s] = sum;
            }
        }
        System.arraycopy(e, 0, rhs, 0, 6);
        Dense.solveSpd(jjt, rhs, 6);
        double[] dq = new double[n];
        for (int c = 0; c < n; c++) {
            if (frozen[c]) {
                continue;
            }
            double sum = 0;
            for (int r = 0; r < 6; r++) {
                sum += jac[r * n + c] * rhs[r];
            }
            dq[c] = sum;
        }
        return dq;
    }

    private static Vec3 clampNorm(Vec3 v, double max) {
        double n = v.norm();
        return n > max ? v.times(max / n) : v;
    }
}
