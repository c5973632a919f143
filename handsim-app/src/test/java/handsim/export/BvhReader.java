package handsim.export;

import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A small BVH reader for tests, from the format's usual reading: joints with an offset in their
 * parent's frame and channels; a joint's local transform is its offset (plus its position
 * channels) and the product of its rotation channels in the order listed, in degrees.
 */
final class BvhReader {

    /** A joint of the hierarchy and where its channels lie in a frame's values. */
    record Joint(String name, int parent, Vec3 offset, List<String> channels, int firstValue) {
    }

    final Map<String, Joint> joints = new LinkedHashMap<>();
    final List<Joint> order = new ArrayList<>();
    final List<double[]> frames = new ArrayList<>();
    double frameTime;

    static BvhReader read(Path file) throws IOException {
        BvhReader r = new BvhReader();
        String[] t = Files.readString(file).trim().split("\\s+");
        int i = 0, values = 0;
        Deque<Integer> stack = new ArrayDeque<>();
        String pending = null;
        boolean endSite = false;
        if (!t[i++].equals("HIERARCHY")) {
            throw new IOException("no HIERARCHY");
        }
        while (!t[i].equals("MOTION")) {
            switch (t[i]) {
                case "ROOT", "JOINT" -> {
                    pending = t[i + 1];
                    i += 2;
                }
                case "End" -> {
                    endSite = true;
                    i += 2;
                }
                case "{" -> {
                    if (!endSite) {
                        // the enclosing joint is the parent
                        r.order.add(new Joint(pending, stack.isEmpty() ? -1 : stack.peek(), null, List.of(), values));
                    }
                    stack.push(endSite ? -2 : r.order.size() - 1);
                    i++;
                }
                case "}" -> {
                    stack.pop();
                    endSite = false;
                    i++;
                }
                case "OFFSET" -> {
                    Vec3 o = new Vec3(Double.parseDouble(t[i + 1]), Double.parseDouble(t[i + 2]), Double.parseDouble(t[i + 3]));
                    if (!endSite) {
                        Joint j = r.order.get(r.order.size() - 1);
                        r.order.set(r.order.size() - 1, new Joint(j.name(), j.parent(), o, j.channels(), j.firstValue()));
                    }
                    i += 4;
                }
                case "CHANNELS" -> {
                    int n = Integer.parseInt(t[i + 1]);
                    Joint j = r.order.get(r.order.size() - 1);
                    r.order.set(r.order.size() - 1, new Joint(j.name(), j.parent(), j.offset(),
                            List.of(java.util.Arrays.copyOfRange(t, i + 2, i + 2 + n)), values));
                    values += n;
                    i += 2 + n;
                }
                default -> throw new IOException("unexpected " + t[i]);
            }
        }
        r.order.forEach(j -> r.joints.put(j.name(), j));
        i++;
        int frames = Integer.parseInt(t[i + 1]);
        r.frameTime = Double.parseDouble(t[i + 4]);
        i += 5;
        for (int f = 0; f < frames; f++) {
            double[] v = new double[values];
            for (int k = 0; k < values; k++) {
                v[k] = Double.parseDouble(t[i++]);
            }
            r.frames.add(v);
        }
        return r;
    }

    /** The channel's value in frame {@code f} (degrees or metres), or 0 if the joint has no such channel. */
    double value(Joint j, String channel, int f) {
        int k = j.channels().indexOf(channel);
        return k < 0 ? 0 : frames.get(f)[j.firstValue() + k];
    }

    /** The joint's rotation relative to its parent in frame {@code f} (null: every channel 0). */
    Quat rotation(Joint j, double[] frame) {
        Quat r = Quat.IDENTITY;
        for (int k = 0; k < j.channels().size(); k++) {
            String c = j.channels().get(k);
            if (c.endsWith("rotation")) {
                double a = frame == null ? 0 : Math.toRadians(frame[j.firstValue() + k]);
                Vec3 axis = c.startsWith("X") ? Vec3.X : c.startsWith("Y") ? Vec3.Y : Vec3.Z;
                r = r.mul(Quat.fromAxisAngle(axis, a));
            }
        }
        return r;
    }

    /** The joint's world frame in frame {@code f} (or with every channel 0 for f = -1). */
    Frame world(Joint j, int f) {
        double[] frame = f < 0 ? null : frames.get(f);
        Vec3 t = j.offset();
        if (frame != null) {
            t = t.plus(new Vec3(value(j, "Xposition", f), value(j, "Yposition", f), value(j, "Zposition", f)));
        }
        Frame local = new Frame(t, rotation(j, frame));
        return j.parent() < 0 ? local : world(order.get(j.parent()), f).compose(local);
    }
}
