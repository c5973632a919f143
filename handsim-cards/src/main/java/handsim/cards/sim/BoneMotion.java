package handsim.cards.sim;

/**
 * Bone control (thesis 3.2.3): the bone nodes of each fingertip follow a rigid motion, given here
 * as the translation of that fingertip's bone from its starting place at time t (metres).
 */
public interface BoneMotion {

    /** Translation of fingertip {@code finger}'s bone at time t, written to out[0..2]. */
    void translation(int finger, double t, double[] out);

    /** No motion: bones stay where they start. */
    BoneMotion STILL = (finger, t, out) -> java.util.Arrays.fill(out, 0, 3, 0.0);
}
