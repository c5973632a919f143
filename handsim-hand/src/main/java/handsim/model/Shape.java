package handsim.model;

import handsim.math.Quat;
import handsim.math.Vec3;

/**
 * A collision and mass shape in a body's frame. Capsules and cylinders are given by their
 * segment end points; boxes by centre, full size and rotation.
 */
public sealed interface Shape {

    /** Volume in m^3 (used to spread a body's mass over its shapes). */
    double volume();

    /** Centre of volume in the body frame. */
    Vec3 centroid();

    /** Capsule: the set of points within {@code radius} of the segment from {@code a} to {@code b}. */
    record Capsule(Vec3 a, Vec3 b, double radius) implements Shape {
        public double length() {
            return a.distance(b);
        }

        public double volume() {
            return Math.PI * radius * radius * (length() + 4.0 / 3.0 * radius);
        }

        public Vec3 centroid() {
            return a.lerp(b, 0.5);
        }
    }

    /** Solid cylinder with flat caps at {@code a} and {@code b}. */
    record Cylinder(Vec3 a, Vec3 b, double radius) implements Shape {
        public double length() {
            return a.distance(b);
        }

        public double volume() {
            return Math.PI * radius * radius * length();
        }

        public Vec3 centroid() {
            return a.lerp(b, 0.5);
        }
    }

    /** Box with full edge lengths {@code size}, rotated by {@code rotation} about its centre. */
    record Box(Vec3 center, Vec3 size, Quat rotation) implements Shape {
        public double volume() {
            return size.x() * size.y() * size.z();
        }

        public Vec3 centroid() {
            return center;
        }
    }

    record Sphere(Vec3 center, double radius) implements Shape {
        public double volume() {
            return 4.0 / 3.0 * Math.PI * radius * radius * radius;
        }

        public Vec3 centroid() {
            return center;
        }
    }
}
