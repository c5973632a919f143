package handsim.mesh;

import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Shape;
import java.util.List;

/**
 * Triangle meshes of shapes in their own frame (a body's, an object's): capsules as a tube closed
 * by two hemispheres, cylinders as a tube closed by two flat caps, boxes, spheres; and the flat
 * pieces of the stage (floor tiles, the goal plane). Front faces point out of the solid.
 */
public final class ShapeMeshes {

    private ShapeMeshes() {
    }

    /** All of {@code shapes} in one mesh, each cut at {@code detail} (see {@link Detail#forShape}). */
    public static TriangleMesh of(List<Shape> shapes, Detail detail) {
        MeshBuilder b = new MeshBuilder();
        for (Shape s : shapes) {
            add(b, s, detail.forShape(s));
        }
        return b.build();
    }

    /** One shape, cut at {@code detail} (see {@link Detail#forShape}). */
    public static TriangleMesh of(Shape shape, Detail detail) {
        return of(List.of(shape), detail);
    }

    /** An axis-aligned box of full edge lengths {@code size} about {@code center}. */
    public static TriangleMesh box(Vec3 center, Vec3 size) {
        MeshBuilder b = new MeshBuilder();
        box(b, center, size, Quat.IDENTITY);
        return b.build();
    }

    /**
     * The square {@code |x|, |z| <= half} in the plane y = 0, facing up (+y): the goal plane. As
     * the viewer does, a consumer shows it from both sides.
     */
    public static TriangleMesh square(double half) {
        MeshBuilder b = new MeshBuilder();
        tile(b, -half, -half, 2 * half);
        return b.build();
    }

    /**
     * The floor's tiles of one colour in the plane y = 0, facing up: the checkered square
     * {@code |x|, |z| <= half} cut into tiles of side {@code tile}, those whose grid indices (i, k)
     * have an even sum ({@code even}) or an odd one.
     */
    public static TriangleMesh checker(double half, double tile, boolean even) {
        MeshBuilder b = new MeshBuilder();
        int n = (int) Math.round(half / tile);
        for (int i = -n; i < n; i++) {
            for (int k = -n; k < n; k++) {
                if ((((i + k) & 1) == 0) == even) {
                    tile(b, i * tile, k * tile, tile);
                }
            }
        }
        return b.build();
    }

    private static void tile(MeshBuilder b, double x0, double z0, double side) {
        b.quad(b.vertex(new Vec3(x0, 0, z0), Vec3.Y), b.vertex(new Vec3(x0, 0, z0 + side), Vec3.Y),
                b.vertex(new Vec3(x0 + side, 0, z0 + side), Vec3.Y), b.vertex(new Vec3(x0 + side, 0, z0), Vec3.Y));
    }

    private static void add(MeshBuilder b, Shape shape, Detail d) {
        if (shape instanceof Shape.Sphere s) {
            Axis axis = new Axis(s.center(), Vec3.Z);
            sphereBands(b, axis, s.radius(), -d.hemiStacks, d.hemiStacks, d);
        } else if (shape instanceof Shape.Capsule c) {
            // a tube from a to b closed by a hemisphere at each end, facing outward
            Axis axis = Axis.along(c.a(), c.b());
            double length = c.a().distance(c.b());
            tube(b, axis, c.radius(), length, d);
            sphereBands(b, axis, c.radius(), -d.hemiStacks, 0, d);
            sphereBands(b, axis.movedBy(length), c.radius(), 0, d.hemiStacks, d);
        } else if (shape instanceof Shape.Cylinder c) {
            Axis axis = Axis.along(c.a(), c.b());
            double length = c.a().distance(c.b());
            tube(b, axis, c.radius(), length, d);
            cap(b, axis, c.radius(), false, d);
            cap(b, axis.movedBy(length), c.radius(), true, d);
        } else if (shape instanceof Shape.Box x) {
            box(b, x.center(), x.size(), x.rotation());
        }
    }

    /**
     * A line through {@code origin} along unit {@code w}, with unit {@code u}, {@code v} across it
     * (u, v, w right-handed): round shapes are laid out around it.
     */
    private record Axis(Vec3 origin, Vec3 u, Vec3 v, Vec3 w) {
        Axis(Vec3 origin, Vec3 w) {
            this(origin, w.anyPerpendicular().normalized(), w.cross(w.anyPerpendicular().normalized()), w);
        }

        static Axis along(Vec3 a, Vec3 b) {
            return new Axis(a, b.minus(a).normalized());
        }

        Axis movedBy(double h) {
            return new Axis(origin.plus(w.times(h)), u, v, w);
        }

        /** The unit direction at longitude p and latitude t (t = pi/2 along w). */
        Vec3 direction(double t, double p) {
            return u.times(Math.cos(t) * Math.cos(p)).plus(v.times(Math.cos(t) * Math.sin(p))).plus(w.times(Math.sin(t)));
        }
    }

    /**
     * Latitude bands of the sphere of {@code radius} about the axis origin, from band {@code from}
     * to {@code to} ({@code d.hemiStacks} bands per hemisphere; negative bands lie toward -w). A
     * quad steps east (longitude) then north, so (east x north) is outward: counter-clockwise
     * seen from outside.
     */
    private static void sphereBands(MeshBuilder b, Axis axis, double radius, int from, int to, Detail d) {
        int first = -1;
        for (int i = from; i <= to; i++) {
            double t = Math.PI / 2 * i / d.hemiStacks;
            for (int j = 0; j <= d.slices; j++) {
                Vec3 n = axis.direction(t, 2 * Math.PI * j / d.slices);
                int index = b.vertex(axis.origin().plus(n.times(radius)), n);
                first = first < 0 ? index : first;
            }
        }
        grid(b, first, to - from, d.slices, from == -d.hemiStacks, to == d.hemiStacks);
    }

    /** The side of the cylinder of {@code radius} from the axis origin to {@code length} along w. */
    private static void tube(MeshBuilder b, Axis axis, double radius, double length, Detail d) {
        int first = -1;
        for (double h : new double[] {0, length}) {
            for (int j = 0; j <= d.slices; j++) {
                Vec3 n = axis.direction(0, 2 * Math.PI * j / d.slices);
                int index = b.vertex(axis.origin().plus(n.times(radius)).plus(axis.w().times(h)), n);
                first = first < 0 ? index : first;
            }
        }
        grid(b, first, 1, d.slices, false, false);
    }

    /**
     * Quads between {@code rows + 1} rings of {@code slices + 1} vertices each (east, then north);
     * a ring that is a pole (all its vertices at one point) gets triangles, not flat quads.
     */
    private static void grid(MeshBuilder b, int first, int rows, int slices, boolean southPole, boolean northPole) {
        int ring = slices + 1;
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < slices; j++) {
                int sw = first + i * ring + j, se = sw + 1, ne = se + ring, nw = sw + ring;
                if (!(southPole && i == 0)) {
                    b.triangle(sw, se, ne);
                }
                if (!(northPole && i == rows - 1)) {
                    b.triangle(sw, ne, nw);
                }
            }
        }
    }

    /**
     * A flat disc at the axis origin closing a cylinder: facing +w ({@code top}) or -w. Its fan
     * turns counter-clockwise seen from the side it faces.
     */
    private static void cap(MeshBuilder b, Axis axis, double radius, boolean top, Detail d) {
        Vec3 n = top ? axis.w() : axis.w().negate();
        int centre = b.vertex(axis.origin(), n);
        int first = -1;
        for (int j = 0; j <= d.slices; j++) {
            int index = b.vertex(axis.origin().plus(axis.direction(0, 2 * Math.PI * j / d.slices).times(radius)), n);
            first = first < 0 ? index : first;
        }
        for (int j = 0; j < d.slices; j++) {
            if (top) {
                b.triangle(centre, first + j, first + j + 1);
            } else {
                b.triangle(centre, first + j + 1, first + j);
            }
        }
    }

    /** A box of full edge lengths {@code size} about {@code center}, turned by {@code rotation}: four vertices per face. */
    private static void box(MeshBuilder b, Vec3 center, Vec3 size, Quat rotation) {
        Vec3[] axes = {Vec3.X, Vec3.Y, Vec3.Z};
        Vec3 half = size.times(0.5);
        for (int k = 0; k < 3; k++) {
            for (int sign = -1; sign <= 1; sign += 2) {
                // face normal n = sign e_k; (s, t) across it with s x t = n, so (-s-t, s-t, s+t, -s+t) turns counter-clockwise
                Vec3 n = axes[k].times(sign);
                Vec3 s = axes[(k + 1) % 3].times(sign * half.get((k + 1) % 3));
                Vec3 t = axes[(k + 2) % 3].times(half.get((k + 2) % 3));
                Vec3 mid = n.times(half.get(k));
                Vec3 worldN = rotation.rotate(n);
                int[] c = new int[4];
                double[][] st = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
                for (int i = 0; i < 4; i++) {
                    Vec3 local = mid.plus(s.times(st[i][0])).plus(t.times(st[i][1]));
                    c[i] = b.vertex(center.plus(rotation.rotate(local)), worldN);
                }
                b.quad(c[0], c[1], c[2], c[3]);
            }
        }
    }
}
