package handsim.viewer;

import static org.lwjgl.opengl.GL11.*;

import handsim.mesh.Detail;
import handsim.mesh.ShapeMeshes;
import handsim.mesh.TriangleMesh;
import handsim.model.HandModel;
import handsim.model.Shape;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Display lists of the {@link ShapeMeshes} of one {@link Detail}: one per body of the model
 * drawn, one per object (the few last seen: an object's size varies from episode to episode).
 * Needs a current OpenGL context.
 */
final class MeshLists implements AutoCloseable {

    /** Objects whose lists are kept; an older one's list is deleted when a new object comes. */
    static final int OBJECTS_KEPT = 4;

    private final Detail detail;
    private HandModel model;
    private int bodies;
    private final Map<List<Shape>, Integer> objects = new LinkedHashMap<>();

    MeshLists(Detail detail) {
        this.detail = detail;
    }

    /** The list drawing body {@code body} of {@code model} in its own frame. */
    int body(HandModel m, int body) {
        if (m != model) {
            deleteBodies();
            model = m;
            bodies = glGenLists(m.bodyCount());
            for (int b = 0; b < m.bodyCount(); b++) {
                compile(bodies + b, ShapeMeshes.of(m.bodies().get(b).shapes(), detail));
            }
        }
        return bodies + body;
    }

    /** The list drawing an object of {@code shapes} in its own frame. */
    int object(List<Shape> shapes) {
        Integer list = objects.get(shapes);
        if (list == null) {
            if (objects.size() >= OBJECTS_KEPT) {
                var oldest = objects.entrySet().iterator().next();
                glDeleteLists(oldest.getValue(), 1);
                objects.remove(oldest.getKey());
            }
            list = glGenLists(1);
            compile(list, ShapeMeshes.of(shapes, detail));
            objects.put(shapes, list);
        }
        return list;
    }

    /** Compiles {@code mesh} into display list {@code list}. */
    static void compile(int list, TriangleMesh mesh) {
        glNewList(list, GL_COMPILE);
        draw(mesh);
        glEndList();
    }

    /** Draws {@code mesh}'s triangles with their normals. */
    static void draw(TriangleMesh mesh) {
        glBegin(GL_TRIANGLES);
        for (int t = 0; t < mesh.triangleCount(); t++) {
            for (int c = 0; c < 3; c++) {
                int v = mesh.corner(t, c);
                glNormal3f(mesh.normal(v, 0), mesh.normal(v, 1), mesh.normal(v, 2));
                glVertex3f(mesh.position(v, 0), mesh.position(v, 1), mesh.position(v, 2));
            }
        }
        glEnd();
    }

    private void deleteBodies() {
        if (model != null) {
            glDeleteLists(bodies, model.bodyCount());
            model = null;
        }
    }

    @Override
    public void close() {
        deleteBodies();
        objects.values().forEach(list -> glDeleteLists(list, 1));
        objects.clear();
    }
}
