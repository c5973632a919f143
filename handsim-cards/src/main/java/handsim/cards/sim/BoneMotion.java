package handsim.cards.sim;

/**
 * Bone control (thesis 3.2.3): the bone nodes of each fingertip follow a rigid motion, given here
 * as a turn about the bone's rest centre (the centroid of its bone nodes) followed by a
 * translation of that centre from its starting place at time t.
 */
public interface BoneMotion {

    /** Translation of fingertip {@code finger}'s bone at time t, written to out[0..2] (m). */
    void translation(int finger, double t, double[] out);

    /**
     * Turn of fingertip {@code finger}'s bone about its rest centre at time t, as a rotation
     * vector (unit axis times angle, radians) written to out[0..2]; no turn by default.
     */
    default void rotation(int finger, double t, double[] out) {
        java.util.Arrays.fill(out, 0, 3, 0.0);
    }

    /** No motion: bones stay where they start. */
    BoneMotion STILL = (finger, t, out) -> java.util.Arrays.fill(out, 0, 3, 0.0);
}
