package handsim.viewer;

import static org.lwjgl.opengl.GL11.*;

import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.Shape;
import handsim.sim.WorldSnapshot;
import java.util.List;

/**
 * Draws a {@link WorldSnapshot} with OpenGL's fixed-function pipeline (cheap on Mesa's software
 * renderer): a checkered floor, planar shadows of every shape, shaded capsules, cylinders,
 * boxes and spheres for the arm, the hand, the object and static boxes, and translucent goals.
 * Needs a current OpenGL context; unit meshes are built once into display lists.
 */
public final class SceneRenderer implements AutoCloseable {

    public static final float[] SKIN = {0.87f, 0.70f, 0.58f, 1};
    public static final float[] OBJECT = {1.0f, 0.42f, 0.08f, 1};
    public static final float[] STATIC_BOX = {0.55f, 0.58f, 0.66f, 1};
    public static final float[] GOAL_PLANE = {0.95f, 0.1f, 0.1f, 0.28f};
    public static final float[] BACKGROUND = {0.93f, 0.95f, 0.98f, 1};
    static final float[] FLOOR_LIGHT = {0.82f, 0.82f, 0.80f}, FLOOR_DARK = {0.72f, 0.72f, 0.70f};
    static final double FLOOR_HALF_SIZE = 3, FLOOR_TILE = 0.25;
    static final float SHADOW_ALPHA = 0.35f;
    /** Direction the light travels (down, from the front-right). */
    static final Vec3 LIGHT = new Vec3(-0.35, -1, -0.45).normalized();
    static final int SLICES = 20, STACKS = 12;

    private final int sphereList, cylinderList, cubeList;

    public SceneRenderer() {
        sphereList = glGenLists(3);
        cylinderList = sphereList + 1;
        cubeList = sphereList + 2;
        buildSphere();
        buildCylinder();
        buildCube();
    }

    /** Clears the frame and sets camera, light and state for an image of {@code width} x {@code height}. */
    public void begin(Camera camera, int width, int height) {
        glViewport(0, 0, width, height);
        glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(camera.projection((double) width / height));
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixf(camera.view());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_CULL_FACE);
        glEnable(GL_NORMALIZE);
        glShadeModel(GL_SMOOTH);
        glEnable(GL_LIGHT0);
        glLightfv(GL_LIGHT0, GL_POSITION, new float[] {(float) -LIGHT.x(), (float) -LIGHT.y(), (float) -LIGHT.z(), 0});
        glLightfv(GL_LIGHT0, GL_DIFFUSE, new float[] {0.75f, 0.75f, 0.72f, 1});
        glLightfv(GL_LIGHT0, GL_SPECULAR, new float[] {0.25f, 0.25f, 0.25f, 1});
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, new float[] {0.38f, 0.38f, 0.42f, 1});
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
        glMaterialfv(GL_FRONT, GL_SPECULAR, new float[] {0.3f, 0.3f, 0.3f, 1});
        glMaterialf(GL_FRONT, GL_SHININESS, 24);
    }

    /** Floor, shadows, arm and hand, the object and static boxes (opaque parts first). */
    public void drawWorld(WorldSnapshot s) {
        drawFloor(s.groundHeight());
        drawShadows(s);
        glEnable(GL_LIGHTING);
        drawBodies(s, SKIN);
        drawObject(s);
        for (WorldSnapshot.StaticBox b : s.boxes()) {
            drawBox(b.center(), b.size(), STATIC_BOX);
        }
    }

    /** A translucent horizontal square at {@code height}, centred above {@code center}: the height goal. */
    public void drawGoalPlane(double height, Vec3 center, double halfSize, float[] rgba) {
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(false);
        glColor4f(rgba[0], rgba[1], rgba[2], rgba[3]);
        glBegin(GL_QUADS);
        glVertex3d(center.x() - halfSize, height, center.z() - halfSize);
        glVertex3d(center.x() + halfSize, height, center.z() - halfSize);
        glVertex3d(center.x() + halfSize, height, center.z() + halfSize);
        glVertex3d(center.x() - halfSize, height, center.z() + halfSize);
        glEnd();
        glDepthMask(true);
        glDisable(GL_BLEND);
        glEnable(GL_CULL_FACE);
    }

    /** An axis-aligned box (centre, full size); translucent if alpha < 1. */
    public void drawBox(Vec3 center, Vec3 size, float[] rgba) {
        boolean translucent = rgba[3] < 1;
        glEnable(GL_LIGHTING);
        if (translucent) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(false);
        }
        glColor4f(rgba[0], rgba[1], rgba[2], rgba[3]);
        glPushMatrix();
        glTranslated(center.x(), center.y(), center.z());
        glScaled(size.x() / 2, size.y() / 2, size.z() / 2);
        glCallList(cubeList);
        glPopMatrix();
        if (translucent) {
            glDepthMask(true);
            glDisable(GL_BLEND);
        }
    }

    private void drawBodies(WorldSnapshot s, float[] color) {
        glColor4f(color[0], color[1], color[2], color[3]);
        List<Body> bodies = s.model().bodies();
        for (int i = 0; i < bodies.size(); i++) {
            drawShapes(s.bodies().get(i), bodies.get(i).shapes());
        }
    }

    private void drawObject(WorldSnapshot s) {
        if (s.object().isPresent() && s.objectSpec().isPresent()) {
            glColor4f(OBJECT[0], OBJECT[1], OBJECT[2], OBJECT[3]);
            var o = s.object().get();
            drawShapes(new Frame(o.position(), o.orientation()), s.objectSpec().get().shapes());
        }
    }

    private void drawShapes(Frame frame, List<Shape> shapes) {
        glPushMatrix();
        multiply(frame.origin(), frame.rotation());
        for (Shape shape : shapes) {
            drawShape(shape);
        }
        glPopMatrix();
    }

    private void drawShape(Shape shape) {
        if (shape instanceof Shape.Sphere sp) {
            drawScaled(sp.center(), Quat.IDENTITY, sp.radius(), sp.radius(), sp.radius(), sphereList);
        } else if (shape instanceof Shape.Box b) {
            drawScaled(b.center(), b.rotation(), b.size().x() / 2, b.size().y() / 2, b.size().z() / 2, cubeList);
        } else if (shape instanceof Shape.Cylinder c) {
            drawSegment(c.a(), c.b(), c.radius(), false);
        } else if (shape instanceof Shape.Capsule c) {
            drawSegment(c.a(), c.b(), c.radius(), true);
        }
    }

    /** A cylinder from a to b (unit mesh along +z), with hemispherical caps for a capsule. */
    private void drawSegment(Vec3 a, Vec3 b, double r, boolean rounded) {
        Vec3 d = b.minus(a);
        drawScaled(a, Quat.between(Vec3.Z, d.normalized()), r, r, d.norm(), cylinderList);
        if (rounded) {
            drawScaled(a, Quat.IDENTITY, r, r, r, sphereList);
            drawScaled(b, Quat.IDENTITY, r, r, r, sphereList);
        }
    }

    private void drawScaled(Vec3 at, Quat rotation, double sx, double sy, double sz, int list) {
        glPushMatrix();
        multiply(at, rotation);
        glScaled(sx, sy, sz);
        glCallList(list);
        glPopMatrix();
    }

    /** Shadows projected along the light onto the floor, each pixel darkened once (stencil). */
    private void drawShadows(WorldSnapshot s) {
        double h = s.groundHeight() + 5e-4;
        double kx = LIGHT.x() / LIGHT.y(), kz = LIGHT.z() / LIGHT.y();
        // p' = p - L (p.y - h) / L.y, column-major
        float[] m = {1, 0, 0, 0, (float) -kx, 0, (float) -kz, 0, 0, 0, 1, 0, (float) (kx * h), (float) h, (float) (kz * h), 1};
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        glDepthMask(false);
        glPushMatrix();
        glMultMatrixf(m);
        List<Body> bodies = s.model().bodies();
        glColor4f(0, 0, 0, SHADOW_ALPHA);
        for (int i = 0; i < bodies.size(); i++) {
            drawShapes(s.bodies().get(i), bodies.get(i).shapes());
        }
        if (s.object().isPresent() && s.objectSpec().isPresent()) {
            var o = s.object().get();
            drawShapes(new Frame(o.position(), o.orientation()), s.objectSpec().get().shapes());
        }
        for (WorldSnapshot.StaticBox b : s.boxes()) {
            glPushMatrix();
            glTranslated(b.center().x(), b.center().y(), b.center().z());
            glScaled(b.size().x() / 2, b.size().y() / 2, b.size().z() / 2);
            glCallList(cubeList);
            glPopMatrix();
        }
        glPopMatrix();
        glDepthMask(true);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_BLEND);
        glEnable(GL_CULL_FACE);
    }

    private void drawFloor(double y) {
        glDisable(GL_LIGHTING);
        glBegin(GL_QUADS);
        int n = (int) Math.round(FLOOR_HALF_SIZE / FLOOR_TILE);
        for (int i = -n; i < n; i++) {
            for (int k = -n; k < n; k++) {
                float[] c = ((i + k) & 1) == 0 ? FLOOR_LIGHT : FLOOR_DARK;
                glColor3f(c[0], c[1], c[2]);
                double x0 = i * FLOOR_TILE, z0 = k * FLOOR_TILE;
                glVertex3d(x0, y, z0);
                glVertex3d(x0, y, z0 + FLOOR_TILE);
                glVertex3d(x0 + FLOOR_TILE, y, z0 + FLOOR_TILE);
                glVertex3d(x0 + FLOOR_TILE, y, z0);
            }
        }
        glEnd();
    }

    private static void multiply(Vec3 t, Quat q) {
        double w = q.w(), x = q.x(), y = q.y(), z = q.z();
        glMultMatrixd(new double[] {
            1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y), 0,
            2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x), 0,
            2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y), 0,
            t.x(), t.y(), t.z(), 1});
    }

    private void buildSphere() {
        glNewList(sphereList, GL_COMPILE);
        for (int i = 0; i < STACKS; i++) {
            double t0 = Math.PI * i / STACKS - Math.PI / 2, t1 = Math.PI * (i + 1) / STACKS - Math.PI / 2;
            glBegin(GL_QUAD_STRIP);
            for (int j = 0; j <= SLICES; j++) {
                double p = 2 * Math.PI * j / SLICES;
                for (double t : new double[] {t1, t0}) {
                    double nx = Math.cos(t) * Math.cos(p), ny = Math.cos(t) * Math.sin(p), nz = Math.sin(t);
                    glNormal3d(nx, ny, nz);
                    glVertex3d(nx, ny, nz);
                }
            }
            glEnd();
        }
        glEndList();
    }

    private void buildCylinder() {
        glNewList(cylinderList, GL_COMPILE);
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= SLICES; j++) {
            double p = 2 * Math.PI * j / SLICES, c = Math.cos(p), s = Math.sin(p);
            glNormal3d(c, s, 0);
            glVertex3d(c, s, 1);
            glVertex3d(c, s, 0);
        }
        glEnd();
        for (int cap = 0; cap < 2; cap++) {
            glBegin(GL_TRIANGLE_FAN);
            glNormal3d(0, 0, cap == 0 ? -1 : 1);
            glVertex3d(0, 0, cap);
            for (int j = 0; j <= SLICES; j++) {
                double p = 2 * Math.PI * (cap == 0 ? j : SLICES - j) / SLICES;
                glVertex3d(Math.cos(p), Math.sin(p), cap);
            }
            glEnd();
        }
        glEndList();
    }

    private void buildCube() {
        glNewList(cubeList, GL_COMPILE);
        glBegin(GL_QUADS);
        int[][] faces = {{0, 1}, {0, -1}, {1, 1}, {1, -1}, {2, 1}, {2, -1}};
        for (int[] f : faces) {
            double[] n = new double[3];
            n[f[0]] = f[1];
            glNormal3d(n[0], n[1], n[2]);
            int u = (f[0] + 1) % 3, v = (f[0] + 2) % 3;
            double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int c = 0; c < 4; c++) {
                int idx = f[1] > 0 ? c : 3 - c;
                double[] p = new double[3];
                p[f[0]] = f[1];
                p[u] = corners[idx][0];
                p[v] = corners[idx][1];
                glVertex3d(p[0], p[1], p[2]);
            }
        }
        glEnd();
        glEndList();
    }

    @Override
    public void close() {
        glDeleteLists(sphereList, 3);
    }
}
