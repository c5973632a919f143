package handsim.math;

/** An immutable 3-vector. */
public record Vec3(double x, double y, double z) {

    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 X = new Vec3(1, 0, 0);
    public static final Vec3 Y = new Vec3(0, 1, 0);
    public static final Vec3 Z = new Vec3(0, 0, 1);

    /** Reads three consecutive values of {@code a} starting at {@code offset}. */
    public static Vec3 of(double[] a, int offset) {
        return new Vec3(a[offset], a[offset + 1], a[offset + 2]);
    }

    public static Vec3 of(double[] a) {
        return of(a, 0);
    }

    /** Writes this vector into {@code a} at {@code offset}. */
    public void into(double[] a, int offset) {
        a[offset] = x;
        a[offset + 1] = y;
        a[offset + 2] = z;
    }

    public double[] toArray() {
        return new double[] {x, y, z};
    }

    public double get(int i) {
        return switch (i) {
            case 0 -> x;
            case 1 -> y;
            case 2 -> z;
            default -> throw new IndexOutOfBoundsException(i);
        };
    }

    public Vec3 plus(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    public Vec3 minus(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    public Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    /** {@code this + s * o}. */
    public Vec3 plusScaled(Vec3 o, double s) {
        return new Vec3(x + s * o.x, y + s * o.y, z + s * o.z);
    }

    public Vec3 negate() {
        return new Vec3(-x, -y, -z);
    }

    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double norm() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    public double normSquared() {
        return x * x + y * y + z * z;
    }

    public double distance(Vec3 o) {
        return minus(o).norm();
    }

    /** This vector scaled to unit length; throws for a (near) zero vector. */
    public Vec3 normalized() {
        double n = norm();
        if (n < 1e-12) {
            throw new ArithmeticException("cannot normalize a zero vector");
        }
        return times(1.0 / n);
    }

    /** Linear interpolation {@code (1-s) this + s o}. */
    public Vec3 lerp(Vec3 o, double s) {
        return new Vec3(x + s * (o.x - x), y + s * (o.y - y), z + s * (o.z - z));
    }

    /** Any unit vector perpendicular to this (non-zero) vector. */
    public Vec3 anyPerpendicular() {
        Vec3 a = Math.abs(x) < 0.9 ? X : Y;
        return cross(a).normalized();
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    @Override
    public String toString() {
        return String.format("(%.6g, %.6g, %.6g)", x, y, z);
    }
}
