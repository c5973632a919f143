package handsim.sim;

import handsim.config.Json;
import handsim.math.Vec3;
import handsim.model.MassProperties;
import handsim.model.ModelLoader;
import handsim.model.Shape;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.SplittableRandom;

/**
 * A thrown object from {@code configs/objects/*.json}: shapes in the object frame, whose origin
 * is the centre of mass, total mass, an optional long axis (cans, cuboids, clubs: the axis the
 * hand's z axis aligns with when catching) and the tolerance by which a seed may vary it.
 */
public record ObjectSpec(String name, List<Shape> shapes, MassProperties mass, Optional<Vec3> longAxis,
        double sizeTolerance, double massTolerance) {

    public ObjectSpec {
        shapes = List.copyOf(shapes);
    }

    /**
     * Sanity limits of a thrown object's mass (kg): from a gram to 10 kg, more than a hand holds
     * up. Its shapes have the limits of {@link ModelLoader#parseShape}.
     */
    static final double MIN_MASS = 1e-3, MAX_MASS = 10;

    public static ObjectSpec load(Path file) {
        return parse(Json.load(file));
    }

    public static ObjectSpec parse(Json j) {
        j.allow("comment");
        String name = j.string("name");
        double mass = j.number("mass", MIN_MASS, MAX_MASS);
        List<Shape> shapes = new ArrayList<>();
        for (Json s : j.array("shapes")) {
            shapes.add(ModelLoader.parseShape(s));
        }
        if (shapes.isEmpty()) {
            throw j.fieldError("shapes", "at least one shape is required");
        }
        Optional<Vec3> axis = Optional.empty();
        if (j.has("longAxis")) {
            Vec3 a = j.vec3("longAxis");
            if (a.norm() < 1e-9) {
                throw j.fieldError("longAxis", "must be non-zero, got " + a);
            }
            axis = Optional.of(a.normalized());
        } else {
            j.allow("longAxis");
        }
        Json tol = j.get("tolerance");
        tol.allow("comment");
        double size = tol.number("size", 0, 0.5);
        double massTol = tol.number("mass", 0, 0.5);
        tol.requireNoUnknownFields();
        j.requireNoUnknownFields();
        return centred(name, shapes, mass, axis, size, massTol);
    }

    /** Builds a spec with the shapes moved so that the centre of mass is the origin. */
    static ObjectSpec centred(String name, List<Shape> shapes, double mass, Optional<Vec3> axis, double sizeTol,
            double massTol) {
        Vec3 com = MassProperties.of(shapes, mass).com();
        List<Shape> moved = shapes.stream().map(s -> transform(s, com.negate(), 1.0)).toList();
        return new ObjectSpec(name, moved, MassProperties.of(moved, mass), axis, sizeTol, massTol);
    }

    /** A copy with every length scaled and the mass varied within the tolerances, drawn from {@code rng}. */
    public ObjectSpec randomized(SplittableRandom rng) {
        double scale = 1 + sizeTolerance * (2 * rng.nextDouble() - 1);
        double m = mass.mass() * (1 + massTolerance * (2 * rng.nextDouble() - 1));
        List<Shape> scaled = shapes.stream().map(s -> transform(s, Vec3.ZERO, scale)).toList();
        return centred(name, scaled, m, longAxis, sizeTolerance, massTolerance);
    }

    /** Radius of the smallest origin-centred sphere holding the object. */
    public double boundingRadius() {
        double r = 0;
        for (Shape s : shapes) {
            r = Math.max(r, extent(s));
        }
        return r;
    }

    /** Half the object's thickness across its long axis (its radius for a sphere or can). */
    public double halfThickness() {
        double r = 0;
        for (Shape s : shapes) {
            if (s instanceof Shape.Sphere sp) {
                r = Math.max(r, sp.radius());
            } else if (s instanceof Shape.Capsule c) {
                r = Math.max(r, c.radius());
            } else if (s instanceof Shape.Cylinder c) {
                r = Math.max(r, c.radius());
            } else if (s instanceof Shape.Box b) {
                r = Math.max(r, 0.5 * Math.min(b.size().x(), Math.min(b.size().y(), b.size().z())));
            }
        }
        return r;
    }

    private static double extent(Shape s) {
        if (s instanceof Shape.Sphere sp) {
            return sp.center().norm() + sp.radius();
        }
        if (s instanceof Shape.Capsule c) {
            return Math.max(c.a().norm(), c.b().norm()) + c.radius();
        }
        if (s instanceof Shape.Cylinder c) {
            return Math.max(c.a().norm(), c.b().norm()) + c.radius();
        }
        Shape.Box b = (Shape.Box) s;
        return b.center().norm() + 0.5 * b.size().norm();
    }

    /** The shape translated by {@code offset} and then scaled about the origin. */
    private static Shape transform(Shape s, Vec3 offset, double scale) {
        if (s instanceof Shape.Sphere sp) {
            return new Shape.Sphere(sp.center().plus(offset).times(scale), sp.radius() * scale);
        }
        if (s instanceof Shape.Capsule c) {
            return new Shape.Capsule(c.a().plus(offset).times(scale), c.b().plus(offset).times(scale), c.radius() * scale);
        }
        if (s instanceof Shape.Cylinder c) {
            return new Shape.Cylinder(c.a().plus(offset).times(scale), c.b().plus(offset).times(scale), c.radius() * scale);
        }
        Shape.Box b = (Shape.Box) s;
        return new Shape.Box(b.center().plus(offset).times(scale), b.size().times(scale), b.rotation());
    }
}
