package handsim.task;

import handsim.config.Json;
import handsim.control.Observation;
import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import java.util.Locale;
import java.util.Optional;

/**
 * The learner's state at a THROW decision (paper sec. 3.7): the palm's position and rotation, the
 * object's position in the palm frame and its orientation, with the task's goal appended ("we
 * embed the goal to the state vector", sec. 4.2). Two encodings of the same facts:
 *
 * <ul>
 * <li>{@link Encoding#PAPER}: {@code (p_h, r_h, p_p, r_p, goal)} as printed, with r_h and r_p
 * rotation vectors (world) of the quaternion with w >= 0. The neutral palm is turned almost
 * exactly pi, where a rotation vector jumps to its opposite with the slightest change, and a can
 * that flipped end for end has a rotation vector unrelated to the same can before the flip.</li>
 * <li>{@link Encoding#CONTINUOUS} (handsim's reading): {@code (p_h, R_h e_x, R_h e_y, p_p, a a^T,
 * goal)}: the palm's rotation as the first two columns of its matrix, continuous everywhere
 * (Zhou et al. 2019, "On the continuity of rotation representations"), and the object's long
 * axis {@code a} in the palm frame as the six entries of the dyad {@code a a^T}
 * (xx, yy, zz, xy, xz, yz), which are the same for a and -a (a can end for end is the same can)
 * and ignore the spin about the axis, which a can or club does not care about; zeros for an object
 * without a long axis (a sphere's orientation does not matter to its throw).</li>
 * <li>{@link Encoding#EXTENDED}: the continuous state followed by what it leaves out of a throw's
 * start: the object's velocity and angular velocity in the palm frame ({@code R_h^T v_p}, {@code
 * R_h^T w_p}), every joint angle of the arm and hand (model DOF order, rad), and which bodies of
 * the hand touch the object (1 or 0 per body, model order: the contact joints of the last
 * controller period). Its length depends on the model ({@link Hand}).</li>
 * </ul>
 */
public final class StateVector {

    /** How the state is written; a policy file records the one it was trained with. */
    public enum Encoding {
        PAPER(12), CONTINUOUS(18), EXTENDED(24);

        private final int baseSize;

        Encoding(int baseSize) {
            this.baseSize = baseSize;
        }

        /** Entries before the goal and the hand's ({@link #handSized}). */
        public int baseSize() {
            return baseSize;
        }

        /** Whether the state also has an entry per joint and per hand body, so that its length depends on the model. */
        public boolean handSized() {
            return this == EXTENDED;
        }

        /** The name in configs and policy files: {@code paper} or {@code continuous}. */
        public String label() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** The encoding named {@code label} (in any case); fails naming the choices. */
        public static Encoding parse(String label) {
            for (Encoding e : values()) {
                if (e.label().equalsIgnoreCase(label)) {
                    return e;
                }
            }
            throw new IllegalArgumentException("must be paper, continuous or extended, got \"" + label + "\"");
        }

        /**
         * The {@code state} field of a training config's run section or of a policy file;
         * {@code paper} when absent (what was written before there was a choice).
         */
        public static Encoding read(Json j) {
            try {
                return parse(j.string("state", PAPER.label()));
            } catch (IllegalArgumentException e) {
                throw j.fieldError("state", e.getMessage());
            }
        }
    }

    /**
     * The sizes of the hand the extended state describes: its joint angles (the model's DOFs) and a
     * contact entry per body.
     */
    public record Hand(int joints, int bodies) {

        public Hand {
            if (joints < 0 || bodies < 0 || bodies > Long.SIZE) {
                throw new IllegalArgumentException("a hand of " + joints + " joints and " + bodies + " bodies (at most " + Long.SIZE + ")");
            }
        }

        /** The sizes of {@code model}. */
        public static Hand of(HandModel model) {
            return new Hand(model.dofCount(), model.bodies().size());
        }
    }

    private final Encoding encoding;
    private final Vec3 longAxis;
    private final Hand hand;

    /** The state of {@code encoding} (not a {@link Encoding#handSized} one) for an object with the given long axis (object frame). */
    public StateVector(Encoding encoding, Optional<Vec3> longAxis) {
        this(encoding, longAxis, null);
    }

    /**
     * The state of {@code encoding} for an object with the given long axis (object frame) in
     * {@code hand} (needed by a {@link Encoding#handSized} encoding, else unused and may be null).
     */
    public StateVector(Encoding encoding, Optional<Vec3> longAxis, Hand hand) {
        if (encoding.handSized() && hand == null) {
            throw new IllegalArgumentException("the " + encoding.label() + " state needs the hand's joint and body counts");
        }
        this.encoding = encoding;
        this.longAxis = longAxis.map(Vec3::normalized).orElse(null);
        this.hand = encoding.handSized() ? hand : null;
    }

    public Encoding encoding() {
        return encoding;
    }

    /** The hand's sizes this state describes (null unless the encoding is {@link Encoding#handSized}). */
    public Hand hand() {
        return hand;
    }

    /** Entries of the state with a goal of {@code goalSize} entries. */
    public int size(int goalSize) {
        return baseSize() + goalSize;
    }

    /** Entries before the goal. */
    private int baseSize() {
        return encoding.baseSize() + (hand == null ? 0 : hand.joints() + hand.bodies());
    }

    /** The state for {@code obs} and the goal of the throw about to be made. */
    public double[] encode(Observation obs, double[] goal) {
        int base = baseSize();
        double[] s = new double[base + goal.length];
        Frame palm = obs.palm();
        Quat palmRotation = palm.rotation();
        Vec3 objectInPalm = palmRotation.inverseRotate(obs.object().position().minus(palm.origin()));
        put(s, 0, palm.origin());
        if (encoding == Encoding.PAPER) {
            put(s, 3, palmRotation.toRotationVector());
            put(s, 6, objectInPalm);
            put(s, 9, obs.object().orientation().toRotationVector());
        } else {
            put(s, 3, palmRotation.xAxis());
            put(s, 6, palmRotation.yAxis());
            put(s, 9, objectInPalm);
            if (longAxis != null) {
                Vec3 a = palmRotation.inverseRotate(obs.object().orientation().rotate(longAxis));
                s[12] = a.x() * a.x();
                s[13] = a.y() * a.y();
                s[14] = a.z() * a.z();
                s[15] = a.x() * a.y();
                s[16] = a.x() * a.z();
                s[17] = a.y() * a.z();
            }
            if (hand != null) {
                put(s, 18, palmRotation.inverseRotate(obs.object().velocity()));
                put(s, 21, palmRotation.inverseRotate(obs.object().angularVelocity()));
                if (obs.q().length != hand.joints()) {
                    throw new IllegalArgumentException("the observation has " + obs.q().length + " joint angles, the state "
                            + hand.joints());
                }
                System.arraycopy(obs.q(), 0, s, 24, hand.joints());
                for (int b = 0; b < hand.bodies(); b++) {
                    s[24 + hand.joints() + b] = (obs.touchedBodies() >>> b & 1L) == 1 ? 1 : 0;
                }
            }
        }
        System.arraycopy(goal, 0, s, base, goal.length);
        return s;
    }

    private static void put(double[] s, int at, Vec3 v) {
        s[at] = v.x();
        s[at + 1] = v.y();
        s[at + 2] = v.z();
    }
}
