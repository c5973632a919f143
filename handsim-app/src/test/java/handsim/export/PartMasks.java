package handsim.export;

import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.mesh.Detail;
import handsim.mesh.ShapeMeshes;
import handsim.mesh.TriangleMesh;
import handsim.model.Body;
import handsim.model.HandModel;
import handsim.viewer.Camera;
import java.util.ArrayList;
import java.util.List;

/**
 * Where the hand, the object and the rest of the arm of one sample land in an image, drawn from
 * the simulation's own frames (not from any file): the parts' meshes ({@link ShapeMeshes}) posed
 * by the sample and projected by the viewer's {@link Camera}, filled with a depth test at pixel
 * centres. A small rasterizer: a reference for a renderer that draws the exported file.
 */
final class PartMasks {

    static final int NONE = 0, HAND = 1, OBJECT = 2, ARM = 3;

    final int width;
    final int height;
    /** The part seen at each pixel, rows from the top. */
    final int[] part;

    PartMasks(MotionClip.Sample sample, HandModel model, Camera camera, int width, int height) {
        this.width = width;
        this.height = height;
        part = new int[width * height];
        double[] depth = new double[width * height];
        java.util.Arrays.fill(depth, Double.POSITIVE_INFINITY);
        float[] view = camera.view(), projection = camera.projection((double) width / height);
        int palm = model.body("palm").index();
        for (Body b : model.bodies()) {
            int p = model.isAncestorOrSelf(palm, b.index()) ? HAND : ARM;
            fill(ShapeMeshes.of(b.shapes(), Detail.FINE), sample.body(b.index()), p, view, projection, depth);
        }
        if (sample.objectSpec() != null) {
            fill(ShapeMeshes.of(sample.objectSpec().shapes(), Detail.FINE), sample.objectFrame(), OBJECT, view, projection, depth);
        }
    }

    private void fill(TriangleMesh mesh, Frame frame, int label, float[] view, float[] projection, double[] depth) {
        List<double[]> screen = new ArrayList<>();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            Vec3 w = frame.pointToWorld(new Vec3(mesh.position(v, 0), mesh.position(v, 1), mesh.position(v, 2)));
            double[] eye = transform(view, w.x(), w.y(), w.z(), 1);
            double[] clip = transform(projection, eye[0], eye[1], eye[2], eye[3]);
            // pixel x right, y down; NDC depth is affine across the image, so it interpolates linearly
            screen.add(new double[] {(clip[0] / clip[3] + 1) / 2 * width, (1 - clip[1] / clip[3]) / 2 * height, clip[2] / clip[3]});
        }
        for (int t = 0; t < mesh.triangleCount(); t++) {
            double[] a = screen.get(mesh.corner(t, 0)), b = screen.get(mesh.corner(t, 1)), c = screen.get(mesh.corner(t, 2));
            double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            if (Math.abs(area) < 1e-12) {
                continue;
            }
            int x0 = Math.max(0, (int) Math.floor(Math.min(a[0], Math.min(b[0], c[0])))), x1 = Math.min(width - 1,
                    (int) Math.ceil(Math.max(a[0], Math.max(b[0], c[0]))));
            int y0 = Math.max(0, (int) Math.floor(Math.min(a[1], Math.min(b[1], c[1])))), y1 = Math.min(height - 1,
                    (int) Math.ceil(Math.max(a[1], Math.max(b[1], c[1]))));
            for (int y = y0; y <= y1; y++) {
                for (int x = x0; x <= x1; x++) {
                    double px = x + 0.5, py = y + 0.5;
                    double wa = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
                    double wb = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
                    double wc = 1 - wa - wb;
                    if (wa < 0 || wb < 0 || wc < 0) {
                        continue;
                    }
                    double z = wa * a[2] + wb * b[2] + wc * c[2];
                    int i = y * width + x;
                    if (z >= -1 && z <= 1 && z < depth[i]) {
                        depth[i] = z;
                        part[i] = label;
                    }
                }
            }
        }
    }

    private static double[] transform(float[] m, double x, double y, double z, double w) {
        double[] out = new double[4];
        for (int r = 0; r < 4; r++) {
            out[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r] * w;
        }
        return out;
    }

    /** How many pixels show {@code label}. */
    int count(int label) {
        int n = 0;
        for (int p : part) {
            n += p == label ? 1 : 0;
        }
        return n;
    }
}
