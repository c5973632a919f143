package handsim.math;

import java.util.SplittableRandom;

/** Random directions and rotations for tests, drawn from a seeded generator. */
public final class RandomGeometry {

    private RandomGeometry() {
    }

    public static Vec3 randomUnit(SplittableRandom rng) {
        while (true) {
            Vec3 v = new Vec3(2 * rng.nextDouble() - 1, 2 * rng.nextDouble() - 1, 2 * rng.nextDouble() - 1);
            double n = v.norm();
            if (n > 0.1 && n < 1) {
                return v.times(1 / n);
            }
        }
    }

    public static Quat randomRotation(SplittableRandom rng) {
        return Quat.fromAxisAngle(randomUnit(rng), Math.PI * rng.nextDouble());
    }
}
