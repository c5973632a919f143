package handsim.model;

import handsim.math.Vec3;
import java.util.List;

/**
 * A rigid segment. Its frame is world-aligned in the zero configuration with the origin at its
 * joint's anchor ({@code origin}, world coordinates); {@code mass} holds the centre of mass and
 * the inertia in that frame, {@code shapes} the collision shapes.
 *
 * @param parent index of the parent body, -1 for the body attached to the world
 * @param joint index of the joint that connects this body to its parent
 * @param collides whether the shapes take part in contacts (inner links may be visual only)
 */
public record Body(int index, String name, int parent, int joint, Vec3 origin, MassProperties mass,
        List<Shape> shapes, boolean collides) {

    public Body {
        shapes = List.copyOf(shapes);
    }
}
