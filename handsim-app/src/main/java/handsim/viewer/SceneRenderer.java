package handsim.viewer;

import static org.lwjgl.opengl.GL11.*;

import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.mesh.Detail;
import handsim.mesh.ShapeMeshes;
import handsim.mesh.Surface;
import handsim.model.Body;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.List;

/**
 * Draws a {@link WorldSnapshot} with OpenGL's fixed-function pipeline (cheap on Mesa's software
 * renderer): a checkered floor, planar shadows of every shape, shaded capsules, cylinders,
 * boxes and spheres for the arm, the hand (the palm's collision shapes in their own tone), the
 * object and static boxes; then, on request, the task's goal, the object's trail and the joint
 * axes. Needs a current OpenGL context. The shapes are the triangle meshes of {@link ShapeMeshes}
 * (the ones the animation export writes), built once into display lists; shadows use coarser
 * meshes than the bodies.
 */
public final class SceneRenderer implements AutoCloseable {

    static final double SHADOW_LIFT = 5e-4, GOAL_OUTLINE_WIDTH = 2;

    private final ViewerConfig.Palette colours;
    private final ViewerConfig.Stage stage;
    private final ViewerConfig.Overlays overlays;
    private final double planeHalfSize;
    /** The shapes' meshes as the bodies are drawn, and the coarser ones of the shadows. */
    private final MeshLists fine = new MeshLists(Detail.FINE);
    private final MeshLists coarse = new MeshLists(Detail.SHADOW);
    /** The box from -1 to 1 on every axis: static and goal boxes are it scaled. */
    private final int cube;
    private final int floorList;
    private double floorHeight = Double.NaN;
    private JointAxes axes;

    public SceneRenderer(ViewerConfig config) {
        this.colours = config.colours();
        this.stage = config.stage();
        this.overlays = config.overlays();
        this.planeHalfSize = config.goals().planeHalfSize();
        cube = glGenLists(1);
        MeshLists.compile(cube, ShapeMeshes.box(Vec3.ZERO, new Vec3(2, 2, 2)));
        floorList = glGenLists(1);
    }

    /** Clears the frame and sets camera, light and state for an image of {@code width} x {@code height}. */
    public void begin(Camera camera, int width, int height) {
        float[] bg = colours.background();
        glViewport(0, 0, width, height);
        glClearColor(bg[0], bg[1], bg[2], 1);
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
        Vec3 light = stage.light();
        glLightfv(GL_LIGHT0, GL_POSITION, new float[] {(float) -light.x(), (float) -light.y(), (float) -light.z(), 0});
        glLightfv(GL_LIGHT0, GL_DIFFUSE, new float[] {0.75f, 0.75f, 0.72f, 1});
        glLightfv(GL_LIGHT0, GL_SPECULAR, new float[] {0.25f, 0.25f, 0.25f, 1});
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, new float[] {0.38f, 0.38f, 0.42f, 1});
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
        glMaterialfv(GL_FRONT, GL_SPECULAR, new float[] {0.3f, 0.3f, 0.3f, 1});
        glMaterialf(GL_FRONT, GL_SHININESS, 24);
    }

    /**
     * Deforming surfaces (the card scenes), smooth-shaded with per-vertex normals averaged from
     * their triangles; two-sided surfaces are lit on both faces.
     */
    public void drawSurfaces(java.util.List<SurfaceMesh> surfaces) {
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        for (SurfaceMesh m : surfaces) {
            float[] p = m.positions();
            int[] t = m.triangles();
            float[] normals = new float[p.length];
            for (int k = 0; k < t.length / 3; k++) {
                int a = 3 * t[3 * k];
                int b = 3 * t[3 * k + 1];
                int c = 3 * t[3 * k + 2];
                float ux = p[b] - p[a];
                float uy = p[b + 1] - p[a + 1];
                float uz = p[b + 2] - p[a + 2];
                float vx = p[c] - p[a];
                float vy = p[c + 1] - p[a + 1];
                float vz = p[c + 2] - p[a + 2];
                float nx = uy * vz - uz * vy;
                float ny = uz * vx - ux * vz;
                float nz = ux * vy - uy * vx;
                for (int i : new int[] {a, b, c}) {
                    normals[i] += nx;
                    normals[i + 1] += ny;
                    normals[i + 2] += nz;
                }
            }
            if (m.twoSided()) {
                glDisable(GL_CULL_FACE);
                glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
            }
            color(m.rgba());
            glBegin(GL_TRIANGLES);
            for (int idx : t) {
                glNormal3f(normals[3 * idx], normals[3 * idx + 1], normals[3 * idx + 2]);
                glVertex3f(p[3 * idx], p[3 * idx + 1], p[3 * idx + 2]);
            }
            glEnd();
            if (m.twoSided()) {
                glEnable(GL_CULL_FACE);
                glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
                glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
            }
        }
    }

    /**
     * Floor, shadows, arm and hand, the object and static boxes (the opaque parts). Floor and
     * shadows lie under everything else and are drawn first without the depth buffer, which
     * saves a depth test and write on half the screen.
     */
    public void drawWorld(WorldSnapshot s) {
        glDisable(GL_DEPTH_TEST);
        drawFloor(s.groundHeight());
        drawShadows(s);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        List<Body> bodies = s.model().bodies();
        for (int i = 0; i < bodies.size(); i++) {
            color(Surface.of(bodies.get(i)) == Surface.PALM ? colours.palm() : colours.skin());
            drawAt(s.bodies().get(i), fine.body(s.model(), i));
        }
        if (s.object().isPresent() && s.objectSpec().isPresent()) {
            color(colours.object());
            var o = s.object().get();
            drawAt(new Frame(o.position(), o.orientation()), fine.object(s.objectSpec().get().shapes()));
        }
        for (WorldSnapshot.StaticBox b : s.boxes()) {
            drawBox(b.center(), b.size(), colours.staticBox());
        }
    }

    /** The task's goal: a translucent plane with a solid rim for a height, a translucent box for a box. */
    public void drawGoal(Goal goal) {
        if (goal instanceof Goal.Height h) {
            drawGoalPlane(h.height(), h.center(), planeHalfSize, colours.goalPlane());
        } else if (goal instanceof Goal.Box b) {
            drawBox(b.center(), b.size(), colours.goalBox());
        }
    }

    private void drawGoalPlane(double height, Vec3 center, double half, float[] rgba) {
        double[][] corners = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(false);
        glColor4f(rgba[0], rgba[1], rgba[2], rgba[3]);
        glBegin(GL_QUADS);
        for (double[] c : corners) {
            glVertex3d(center.x() + c[0], height, center.z() + c[1]);
        }
        glEnd();
        glLineWidth((float) GOAL_OUTLINE_WIDTH);
        glColor4f(rgba[0], rgba[1], rgba[2], Math.min(1, 3 * rgba[3]));
        glBegin(GL_LINE_LOOP);
        for (double[] c : corners) {
            glVertex3d(center.x() + c[0], height, center.z() + c[1]);
        }
        glEnd();
        glDepthMask(true);
        glDisable(GL_BLEND);
        glEnable(GL_CULL_FACE);
    }

    /** The object's recent path as a line that fades with age; {@code now} is the snapshot's time. */
    public void drawTrail(Trail trail, double now) {
        if (trail.size() < 2) {
            return;
        }
        float[] c = colours.trail();
        glDisable(GL_LIGHTING);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glLineWidth((float) overlays.trailWidthPixels());
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < trail.size(); i++) {
            double age = Math.max(0, now - trail.time(i)) / trail.seconds();
            glColor4f(c[0], c[1], c[2], (float) (c[3] * Math.max(0, 1 - age)));
            Vec3 p = trail.position(i);
            glVertex3d(p.x(), p.y(), p.z());
        }
        glEnd();
        glDisable(GL_BLEND);
    }

    /** Every DOF's rotation axis as a short line from its joint, drawn over the bodies. */
    public void drawJointAxes(WorldSnapshot s) {
        if (axes == null || axes.model() != s.model()) {
            axes = new JointAxes(s.model());
        }
        glDisable(GL_LIGHTING);
        glDisable(GL_DEPTH_TEST);
        glLineWidth((float) overlays.axisWidthPixels());
        glBegin(GL_LINES);
        for (JointAxes.Axis a : axes.compute(s)) {
            float[] c = colours.axes().get(a.slot());
            glColor4f(c[0], c[1], c[2], c[3]);
            Vec3 from = a.anchor(), to = a.anchor().plus(a.direction().times(overlays.axisLength()));
            glVertex3d(from.x(), from.y(), from.z());
            glVertex3d(to.x(), to.y(), to.z());
        }
        glEnd();
        glEnable(GL_DEPTH_TEST);
    }

    /** An axis-aligned box (centre, full size); translucent if alpha < 1. */
    private void drawBox(Vec3 center, Vec3 size, float[] rgba) {
        boolean translucent = rgba[3] < 1;
        glEnable(GL_LIGHTING);
        if (translucent) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(false);
        }
        color(rgba);
        glPushMatrix();
        glTranslated(center.x(), center.y(), center.z());
        glScaled(size.x() / 2, size.y() / 2, size.z() / 2);
        glCallList(cube);
        glPopMatrix();
        if (translucent) {
            glDepthMask(true);
            glDisable(GL_BLEND);
        }
    }

    private static void color(float[] c) {
        glColor4f(c[0], c[1], c[2], c[3]);
    }

    /** Calls display list {@code list} in {@code frame}. */
    private static void drawAt(Frame frame, int list) {
        glPushMatrix();
        multiply(frame.origin(), frame.rotation());
        glCallList(list);
        glPopMatrix();
    }

    /** Shadows projected along the light onto the floor, each pixel darkened once (stencil). */
    private void drawShadows(WorldSnapshot s) {
        double h = s.groundHeight() + SHADOW_LIFT;
        Vec3 light = stage.light();
        double kx = light.x() / light.y(), kz = light.z() / light.y();
        // p' = p - L (p.y - h) / L.y, column-major
        float[] m = {1, 0, 0, 0, (float) -kx, 0, (float) -kz, 0, 0, 0, 1, 0, (float) (kx * h), (float) h, (float) (kz * h), 1};
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        glPushMatrix();
        glMultMatrixf(m);
        color(colours.shadow());
        for (int i = 0; i < s.model().bodyCount(); i++) {
            drawAt(s.bodies().get(i), coarse.body(s.model(), i));
        }
        if (s.object().isPresent() && s.objectSpec().isPresent()) {
            var o = s.object().get();
            drawAt(new Frame(o.position(), o.orientation()), coarse.object(s.objectSpec().get().shapes()));
        }
        for (WorldSnapshot.StaticBox b : s.boxes()) {
            glPushMatrix();
            glTranslated(b.center().x(), b.center().y(), b.center().z());
            glScaled(b.size().x() / 2, b.size().y() / 2, b.size().z() / 2);
            glCallList(cube);
            glPopMatrix();
        }
        glPopMatrix();
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_BLEND);
        glEnable(GL_CULL_FACE);
    }

    private void drawFloor(double y) {
        if (y != floorHeight) {
            buildFloor(y);
        }
        glDisable(GL_LIGHTING);
        glCallList(floorList);
    }

    /** The checkered floor at height y: the tiles of each colour as {@link ShapeMeshes#checker} lays them out. */
    private void buildFloor(double y) {
        floorHeight = y;
        glNewList(floorList, GL_COMPILE);
        glPushMatrix();
        glTranslated(0, y, 0);
        for (boolean even : new boolean[] {true, false}) {
            float[] c = even ? colours.floorLight() : colours.floorDark();
            glColor3f(c[0], c[1], c[2]);
            MeshLists.draw(ShapeMeshes.checker(stage.floorHalfSize(), stage.floorTile(), even));
        }
        glPopMatrix();
        glEndList();
    }

    private static void multiply(Vec3 t, Quat q) {
        double w = q.w(), x = q.x(), y = q.y(), z = q.z();
        glMultMatrixd(new double[] {
            1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y), 0,
            2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x), 0,
            2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y), 0,
            t.x(), t.y(), t.z(), 1});
    }

    @Override
    public void close() {
        fine.close();
        coarse.close();
        glDeleteLists(cube, 1);
        glDeleteLists(floorList, 1);
    }
}
