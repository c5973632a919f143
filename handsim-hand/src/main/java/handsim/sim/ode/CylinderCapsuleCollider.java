package handsim.sim.ode;

import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DColliderFn;
import org.ode4j.ode.DContactGeom;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DCylinder;
import org.ode4j.ode.DGeom;

/**
 * Contact between a cylinder (the can) and a capsule (a finger), computed from the cylinder's
 * signed distance function instead of libccd.
 *
 * <p>Why: ode4j has no analytic cylinder-capsule collider; with libccd it takes the single
 * penetration point of libccd's MPR search, which jumps as the can rocks on a finger and turns
 * round-off into degrees of the can's turn within two catches (docs/experiments.md,
 * "Contacts"). Here the contact is a continuous function of the two poses: the capsule's axis
 * segment p(s) = c + s u, |s| <= l/2, is searched for the point nearest the cylinder, where the
 * signed distance f(s) = sdf(p(s)) is smallest; f is convex (the cylinder is), so its slope
 * f'(s) = grad sdf . u only rises along the segment and bisection on its sign finds the minimum
 * to round-off. One contact there, with depth r - f(s*), as ODE's capsule-capsule gives one
 * contact for crossing capsules. A capsule lying parallel to the cylinder's side or flat on a
 * cap (within {@link #PARALLEL}) gets its two ends as contacts instead, as ODE does for parallel
 * capsules.
 */
final class CylinderCapsuleCollider implements DColliderFn {

    /** |cos| of the angle within which the capsule counts as parallel to a face (ODE's capsule-capsule tolerance). */
    static final double PARALLEL = 1e-5;

    private static final int BISECTIONS = 64;

    /** Doubles per contact in {@link #collide}'s output: position, normal (cylinder to capsule), depth. */
    static final int CONTACT = 7;

    // scratch, so that a step allocates nothing: one collider per simulator, one thread at a time
    private final double[] cylinderPose = new double[6];
    private final double[] capsulePose = new double[6];
    private final double[] out = new double[2 * CONTACT];
    private final Sdf sdf = new Sdf();

    @Override
    public int dColliderFn(DGeom o1, DGeom o2, int flags, DContactGeomBuffer contacts) {
        boolean cylinderFirst = o1 instanceof DCylinder;
        DCylinder cylinder = (DCylinder) (cylinderFirst ? o1 : o2);
        DCapsule capsule = (DCapsule) (cylinderFirst ? o2 : o1);
        pose(cylinder, cylinderPose);
        pose(capsule, capsulePose);
        int n = collide(cylinderPose, cylinder.getRadius(), 0.5 * cylinder.getLength(),
                capsulePose, capsule.getRadius(), 0.5 * capsule.getLength(), out, flags & 0xffff);
        // out's normals point from the cylinder to the capsule; ODE's from o2 into o1
        double sign = cylinderFirst ? -1 : 1;
        for (int i = 0; i < n; i++) {
            DContactGeom c = contacts.get(i);
            int k = i * CONTACT;
            c.pos.set(out[k], out[k + 1], out[k + 2]);
            c.normal.set(sign * out[k + 3], sign * out[k + 4], sign * out[k + 5]);
            c.depth = out[k + 6];
            c.g1 = o1;
            c.g2 = o2;
            c.side1 = -1;
            c.side2 = -1;
        }
        return n;
    }

    /** A geom's centre and z axis (capsules and cylinders lie along their z axis). */
    private static void pose(DGeom g, double[] pose) {
        DVector3C p = g.getPosition();
        DMatrix3C r = g.getRotation();
        pose[0] = p.get0();
        pose[1] = p.get1();
        pose[2] = p.get2();
        pose[3] = r.get02();
        pose[4] = r.get12();
        pose[5] = r.get22();
    }

    /**
     * The contacts (at most {@code max}, at most 2) of a cylinder (centre and unit axis in
     * {@code cyl}, radius {@code radius}, half-length {@code half}) with a capsule (centre and unit
     * axis in {@code cap}, radius {@code r}, half-length {@code l}), written to {@code out} as
     * {@link #CONTACT} doubles each: the point midway between the two surfaces, the unit normal from
     * the cylinder towards the capsule, and the penetration depth. Returns their number.
     */
    int collide(double[] cyl, double radius, double half, double[] cap, double r, double l,
                double[] out, int max) {
        if (max < 1) {
            return 0;
        }
        sdf.of(cyl, radius, half);
        double cosAxes = cyl[3] * cap[3] + cyl[4] * cap[4] + cyl[5] * cap[5];
        double sStar = minimum(sdf, cap, l);
        sdf.at(cap, sStar);
        if (r - sdf.distance <= 0) {
            return 0;
        }
        boolean lineContact = max >= 2 && l > 0
                && (sdf.onSide() && Math.abs(cosAxes) > 1 - PARALLEL
                    || sdf.onCap() && Math.abs(cosAxes) < PARALLEL);
        if (!lineContact) {
            write(sdf, cap, sStar, r, out, 0);
            return 1;
        }
        int n = 0;
        for (int end = -1; end <= 1; end += 2) {
            sdf.at(cap, end * l);
            if (r - sdf.distance > 0) {
                write(sdf, cap, end * l, r, out, n++ * CONTACT);
            }
        }
        return n;
    }

    /** The s in [-l, l] where the convex f(s) = sdf(c + s u) is least: bisection on the sign of f'. */
    private static double minimum(Sdf sdf, double[] cap, double l) {
        double lo = -l, hi = l;
        if (sdf.at(cap, lo).slope(cap) >= 0) {
            return lo;
        }
        if (sdf.at(cap, hi).slope(cap) <= 0) {
            return hi;
        }
        for (int i = 0; i < BISECTIONS && hi - lo > 0; i++) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            if (sdf.at(cap, mid).slope(cap) < 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    }

    /** Writes the contact of the capsule's sphere at s, whose distance and normal {@code sdf} holds. */
    private static void write(Sdf sdf, double[] cap, double s, double r, double[] out, int k) {
        double px = cap[0] + s * cap[3], py = cap[1] + s * cap[4], pz = cap[2] + s * cap[5];
        // midway between the cylinder's surface (p - f n) and the capsule's (p - r n)
        double back = 0.5 * (sdf.distance + r);
        out[k] = px - back * sdf.nx;
        out[k + 1] = py - back * sdf.ny;
        out[k + 2] = pz - back * sdf.nz;
        out[k + 3] = sdf.nx;
        out[k + 4] = sdf.ny;
        out[k + 5] = sdf.nz;
        out[k + 6] = r - sdf.distance;
    }

    /**
     * The cylinder's signed distance and its gradient at a point: with t the point's coordinate
     * along the axis and rho its distance from it, dx = rho - radius, dy = |t| - half; outside
     * f = |(max(dx,0), max(dy,0))|, inside f = max(dx, dy).
     */
    private static final class Sdf {
        private double[] cyl;
        private double radius;
        private double half;
        double distance;
        double nx, ny, nz;
        private double dx, dy;

        void of(double[] cylinder, double cylinderRadius, double halfLength) {
            cyl = cylinder;
            radius = cylinderRadius;
            half = halfLength;
        }

        Sdf at(double[] cap, double s) {
            double qx = cap[0] + s * cap[3] - cyl[0];
            double qy = cap[1] + s * cap[4] - cyl[1];
            double qz = cap[2] + s * cap[5] - cyl[2];
            double ax = cyl[3], ay = cyl[4], az = cyl[5];
            double t = qx * ax + qy * ay + qz * az;
            double ex = qx - t * ax, ey = qy - t * ay, ez = qz - t * az;
            double rho = Math.sqrt(ex * ex + ey * ey + ez * ez);
            if (rho > 0) {
                ex /= rho;
                ey /= rho;
                ez /= rho;
            } else { // on the axis: any radial direction
                double px = Math.abs(ax) < 0.9 ? 1 : 0, py = px == 1 ? 0 : 1;
                ex = py * az;
                ey = -px * az;
                ez = px * ay - py * ax;
                double len = Math.sqrt(ex * ex + ey * ey + ez * ez);
                ex /= len;
                ey /= len;
                ez /= len;
            }
            double sx = t >= 0 ? ax : -ax, sy = t >= 0 ? ay : -ay, sz = t >= 0 ? az : -az;
            dx = rho - radius;
            dy = Math.abs(t) - half;
            if (dx > 0 && dy > 0) { // beyond the rim
                distance = Math.sqrt(dx * dx + dy * dy);
                nx = (dx * ex + dy * sx) / distance;
                ny = (dx * ey + dy * sy) / distance;
                nz = (dx * ez + dy * sz) / distance;
            } else if (dx >= dy) { // nearest the side
                distance = dx;
                nx = ex;
                ny = ey;
                nz = ez;
            } else { // nearest a cap
                distance = dy;
                nx = sx;
                ny = sy;
                nz = sz;
            }
            return this;
        }

        /** f'(s) at the last point: the gradient along the capsule's axis. */
        double slope(double[] cap) {
            return nx * cap[3] + ny * cap[4] + nz * cap[5];
        }

        boolean onSide() {
            return dx > 0 ? dy <= 0 : dx >= dy;
        }

        boolean onCap() {
            return dy > 0 ? dx <= 0 : dy > dx;
        }
    }
}
