package handsim.mesh;

import handsim.model.Shape;

/**
 * How finely round shapes are cut: {@code slices} around, {@code hemiStacks} latitude bands per
 * hemisphere. The bodies are drawn and exported {@link #FINE} (finger-sized shapes, a few pixels
 * wide on screen, {@link #SMALL}); the viewer's shadows are {@link #SHADOW}.
 */
public enum Detail {
    FINE(20, 6),
    SMALL(12, 4),
    SHADOW(10, 3);

    /** Round shapes thinner than this radius (m: the fingers) are cut as {@link #SMALL} when {@link #FINE} is asked for. */
    public static final double SMALL_RADIUS = 0.015;

    final int slices;
    final int hemiStacks;

    Detail(int slices, int hemiStacks) {
        this.slices = slices;
        this.hemiStacks = hemiStacks;
    }

    /** The detail a shape gets when this one is asked for. */
    Detail forShape(Shape shape) {
        return this == FINE && radius(shape) < SMALL_RADIUS ? SMALL : this;
    }

    /** The radius of a round shape; boxes count as large. */
    private static double radius(Shape shape) {
        if (shape instanceof Shape.Sphere sp) {
            return sp.radius();
        } else if (shape instanceof Shape.Capsule c) {
            return c.radius();
        } else if (shape instanceof Shape.Cylinder c) {
            return c.radius();
        }
        return Double.POSITIVE_INFINITY;
    }
}
