package handsim.export;

import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.HandModel;
import handsim.model.Shape;
import handsim.sim.ObjectSpec;
import java.util.Locale;

/**
 * A {@link MotionClip} as BVH: the arm and hand as a skeleton rooted at the shoulder (a joint per
 * body, named after it, offset from its parent as in the model's zero configuration, where every
 * frame is aligned with the world), each with three rotation channels in the model's Euler
 * order ({@link BvhChannels}); the object as a second root with its centre's position and an
 * x, y, z rotation. One frame per sample, {@code 1 / rate} apart. Metres and degrees. A sample
 * with no object in the world holds the object's nearest pose.
 */
final class BvhWriter {

    private final MotionClip clip;
    private final HandModel model;
    private final BvhChannels[] channels;
    private final StringBuilder out = new StringBuilder();

    private BvhWriter(MotionClip clip) {
        this.clip = clip;
        this.model = clip.model();
        Kinematics kinematics = new Kinematics(model);
        channels = new BvhChannels[model.joints().size()];
        model.joints().forEach(j -> channels[j.index()] = new BvhChannels(model, kinematics, j));
    }

    static String write(MotionClip clip) {
        return new BvhWriter(clip).write();
    }

    private String write() {
        out.append("HIERARCHY\n");
        for (Body b : model.bodies()) {
            if (b.parent() < 0) {
                joint(b, 0);
            }
        }
        ObjectSpec object = clip.samples().stream().map(MotionClip.Sample::objectSpec).filter(s -> s != null).findFirst().orElse(null);
        if (object != null) {
            out.append("ROOT ").append(name(object.name())).append("\n{\n");
            out.append("\tOFFSET 0.000000 0.000000 0.000000\n");
            out.append("\tCHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation Zrotation\n");
            Vec3 tip = object.longAxis().orElse(Vec3.Y).times(object.boundingRadius());
            out.append("\tEnd Site\n\t{\n\t\tOFFSET ").append(vector(tip)).append("\n\t}\n}\n");
        }
        out.append("MOTION\n");
        out.append("Frames: ").append(clip.samples().size()).append('\n');
        out.append(String.format(Locale.ROOT, "Frame Time: %.9f%n", 1 / clip.rate()));
        Frame objectPose = firstObjectPose();
        for (MotionClip.Sample s : clip.samples()) {
            StringBuilder line = new StringBuilder();
            for (Body b : model.bodies()) {
                Frame parent = b.parent() < 0 ? Frame.IDENTITY : s.body(b.parent());
                Quat relative = parent.rotation().conjugate().mul(s.body(b.index()).rotation());
                for (double v : channels[b.joint()].values(relative)) {
                    line.append(degrees(v)).append(' ');
                }
            }
            if (object != null) {
                objectPose = s.objectFrame() != null ? s.objectFrame() : objectPose;
                line.append(vector(objectPose.origin())).append(' ');
                for (double v : Euler.decompose(objectPose.rotation(), new int[] {0, 1, 2})) {
                    line.append(degrees(v)).append(' ');
                }
            }
            out.append(line.toString().trim()).append('\n');
        }
        return out.toString();
    }

    private void joint(Body b, int depth) {
        String tab = "\t".repeat(depth);
        Vec3 parentOrigin = b.parent() < 0 ? Vec3.ZERO : model.bodies().get(b.parent()).origin();
        out.append(tab).append(b.parent() < 0 ? "ROOT " : "JOINT ").append(name(b.name())).append('\n');
        out.append(tab).append("{\n");
        out.append(tab).append("\tOFFSET ").append(vector(b.origin().minus(parentOrigin))).append('\n');
        out.append(tab).append("\tCHANNELS 3");
        for (int axis : channels[b.joint()].order) {
            out.append(' ').append(BvhChannels.NAMES[axis]);
        }
        out.append('\n');
        boolean leaf = true;
        for (Body child : model.bodies()) {
            if (child.parent() == b.index()) {
                joint(child, depth + 1);
                leaf = false;
            }
        }
        if (leaf) {
            out.append(tab).append("\tEnd Site\n").append(tab).append("\t{\n");
            out.append(tab).append("\t\tOFFSET ").append(vector(tip(b))).append('\n');
            out.append(tab).append("\t}\n");
        }
        out.append(tab).append("}\n");
    }

    /** Where a leaf body ends: the end point of its shapes farthest from its joint (a fingertip). */
    private static Vec3 tip(Body b) {
        Vec3 tip = Vec3.ZERO;
        for (Shape s : b.shapes()) {
            Vec3[] ends = s instanceof Shape.Capsule c ? new Vec3[] {c.a(), c.b()}
                    : s instanceof Shape.Cylinder c ? new Vec3[] {c.a(), c.b()} : new Vec3[] {s.centroid()};
            for (Vec3 e : ends) {
                tip = e.norm() > tip.norm() ? e : tip;
            }
        }
        return tip;
    }

    private Frame firstObjectPose() {
        return clip.samples().stream().map(MotionClip.Sample::objectFrame).filter(f -> f != null).findFirst().orElse(Frame.IDENTITY);
    }

    /** BVH names are single words. */
    private static String name(String s) {
        return s.replaceAll("\\s+", "_");
    }

    private static String vector(Vec3 v) {
        return String.format(Locale.ROOT, "%.7f %.7f %.7f", v.x(), v.y(), v.z());
    }

    private static String degrees(double radians) {
        return String.format(Locale.ROOT, "%.6f", Math.toDegrees(radians));
    }
}
