package handsim.model;

import handsim.math.Quat;
import handsim.math.Vec3;

/** A symmetric 3x3 inertia tensor (kg m^2) in some frame, about some point. */
public record Inertia(double xx, double yy, double zz, double xy, double xz, double yz) {

    public static final Inertia ZERO = new Inertia(0, 0, 0, 0, 0, 0);

    public static Inertia diagonal(double xx, double yy, double zz) {
        return new Inertia(xx, yy, zz, 0, 0, 0);
    }

    public Inertia plus(Inertia o) {
        return new Inertia(xx + o.xx, yy + o.yy, zz + o.zz, xy + o.xy, xz + o.xz, yz + o.yz);
    }

    /** Parallel axis theorem: this tensor (about the centre of mass) moved to a point at offset {@code d}. */
    public Inertia shifted(double mass, Vec3 d) {
        double x = d.x(), y = d.y(), z = d.z();
        return new Inertia(
                xx + mass * (y * y + z * z),
                yy + mass * (x * x + z * z),
                zz + mass * (x * x + y * y),
                xy - mass * x * y,
                xz - mass * x * z,
                yz - mass * y * z);
    }

    /** The tensor of the same body rotated by {@code q}: R I R^T. */
    public Inertia rotated(Quat q) {
        Vec3 c0 = q.xAxis(), c1 = q.yAxis(), c2 = q.zAxis();
        double[][] r = {{c0.x(), c1.x(), c2.x()}, {c0.y(), c1.y(), c2.y()}, {c0.z(), c1.z(), c2.z()}};
        double[][] m = {{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}};
        double[][] out = new double[3][3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double s = 0;
                for (int k = 0; k < 3; k++) {
                    for (int l = 0; l < 3; l++) {
                        s += r[i][k] * m[k][l] * r[j][l];
                    }
                }
                out[i][j] = s;
            }
        }
        return new Inertia(out[0][0], out[1][1], out[2][2], out[0][1], out[0][2], out[1][2]);
    }

    /** The tensor times a vector: the angular momentum of a body turning at {@code w} (same frame). */
    public Vec3 times(Vec3 w) {
        return new Vec3(xx * w.x() + xy * w.y() + xz * w.z(), xy * w.x() + yy * w.y() + yz * w.z(),
                xz * w.x() + yz * w.y() + zz * w.z());
    }

    /** The vector {@code w} with {@code this.times(w) = l} (Cramer's rule): the spin of angular momentum l. */
    public Vec3 solve(Vec3 l) {
        double c00 = yy * zz - yz * yz, c01 = xz * yz - xy * zz, c02 = xy * yz - xz * yy;
        double det = xx * c00 + xy * c01 + xz * c02;
        double c11 = xx * zz - xz * xz, c12 = xy * xz - xx * yz, c22 = xx * yy - xy * xy;
        return new Vec3(c00 * l.x() + c01 * l.y() + c02 * l.z(), c01 * l.x() + c11 * l.y() + c12 * l.z(),
                c02 * l.x() + c12 * l.y() + c22 * l.z()).times(1 / det);
    }

    public Inertia scaled(double s) {
        return new Inertia(xx * s, yy * s, zz * s, xy * s, xz * s, yz * s);
    }

    /** True when the tensor is physically valid: positive principal moments obeying the triangle inequality (checked on the diagonal). */
    public boolean isPlausible() {
        return xx > 0 && yy > 0 && zz > 0 && xx + yy >= zz * (1 - 1e-9) && xx + zz >= yy * (1 - 1e-9)
                && yy + zz >= xx * (1 - 1e-9);
    }
}
