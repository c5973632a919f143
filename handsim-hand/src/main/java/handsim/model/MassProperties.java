package handsim.model;

import handsim.math.Quat;
import handsim.math.Vec3;
import java.util.List;

/**
 * Mass, centre of mass and inertia about the centre of mass (body frame axes) of a set of
 * shapes of uniform density, scaled to a given total mass. Overlaps between shapes are counted
 * twice: a simplification that is harmless for limb segments.
 */
public record MassProperties(double mass, Vec3 com, Inertia inertia) {

    /** Uniform density over {@code shapes}, total mass {@code mass}. */
    public static MassProperties of(List<Shape> shapes, double mass) {
        if (shapes.isEmpty()) {
            throw new IllegalArgumentException("at least one shape is needed to derive mass properties");
        }
        double volume = 0;
        Vec3 weighted = Vec3.ZERO;
        for (Shape s : shapes) {
            volume += s.volume();
            weighted = weighted.plus(s.centroid().times(s.volume()));
        }
        double density = mass / volume;
        Vec3 com = weighted.times(1.0 / volume);
        Inertia total = Inertia.ZERO;
        for (Shape s : shapes) {
            double m = density * s.volume();
            total = total.plus(centralInertia(s, m).shifted(m, s.centroid().minus(com)));
        }
        return new MassProperties(mass, com, total);
    }

    /** Inertia of one shape of mass {@code m} about its own centroid, in body axes. */
    static Inertia centralInertia(Shape shape, double m) {
        if (shape instanceof Shape.Sphere s) {
            double i = 0.4 * m * s.radius() * s.radius();
            return Inertia.diagonal(i, i, i);
        }
        if (shape instanceof Shape.Box b) {
            double x = b.size().x(), y = b.size().y(), z = b.size().z();
            return Inertia.diagonal(m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12)
                    .rotated(b.rotation());
        }
        if (shape instanceof Shape.Cylinder c) {
            return alongSegment(c.a(), c.b(), m * (3 * c.radius() * c.radius() + c.length() * c.length()) / 12,
                    0.5 * m * c.radius() * c.radius());
        }
        return capsule((Shape.Capsule) shape, m);
    }

    /** A tensor with axial moment {@code axial} along a-b and {@code transverse} across it. */
    private static Inertia alongSegment(Vec3 a, Vec3 b, double transverse, double axial) {
        Vec3 axis = b.minus(a);
        Quat toAxis = axis.norm() < 1e-12 ? Quat.IDENTITY : Quat.between(Vec3.Z, axis.normalized());
        return Inertia.diagonal(transverse, transverse, axial).rotated(toAxis);
    }

    private static Inertia capsule(Shape.Capsule c, double m) {
        double r = c.radius(), h = c.length();
        double vCyl = Math.PI * r * r * h;
        double vCaps = 4.0 / 3.0 * Math.PI * r * r * r;
        double mCyl = m * vCyl / (vCyl + vCaps);
        double mHemi = 0.5 * (m - mCyl);
        double axial = 0.5 * mCyl * r * r + 2 * (0.4 * mHemi * r * r);
        // each hemisphere: 83/320 m r^2 about its own centroid, centroid 3r/8 from the flat face
        double hemiOffset = h / 2 + 3 * r / 8;
        double transverse = mCyl * (3 * r * r + h * h) / 12
                + 2 * (83.0 / 320.0 * mHemi * r * r + mHemi * hemiOffset * hemiOffset);
        return alongSegment(c.a(), c.b(), transverse, axial);
    }
}
