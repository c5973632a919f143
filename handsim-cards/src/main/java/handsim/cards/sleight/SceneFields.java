package handsim.cards.sleight;

import handsim.config.Json;

/** Field readers the sleights' configs share. */
final class SceneFields {

    private SceneFields() {
    }

    /** {@code n} whole numbers from the array field {@code name}. */
    static int[] ints(Json j, String name, int n) {
        double[] v = j.numbers(name, n);
        int[] out = new int[n];
        for (int i = 0; i < n; i++) {
            if (v[i] != Math.rint(v[i])) {
                throw j.fieldError(name, "expected whole numbers, got " + java.util.Arrays.toString(v));
            }
            out[i] = (int) v[i];
        }
        return out;
    }
}
