package handsim.task;

import handsim.control.ThrowParameters;
import handsim.math.Vec3;

/**
 * One loop of an episode. Loop 0 is the catch of the launched object; loop k >= 1 is the k-th
 * throw and the catch that follows it.
 *
 * @param caught the object was held in the hand at the end of MIDDLE
 * @param apexHeight highest height of the object's centre during the loop's flight (m; NaN for loop 0)
 * @param landing where the object touched the ground when dropped (null if caught)
 * @param targetHeight the apex height the loop's throw aimed at (m; NaN for loop 0)
 * @param throwParams the THROW parameters of the loop (null for loop 0)
 * @param maxPenetration deepest hand-object penetration during the loop (m)
 * @param maxLimitExcess largest excursion of any joint beyond its limit (rad)
 * @param peakTorqueRatio largest |tau| / strength of any DOF (1 = at the human limit; PD torques are clamped)
 * @param duration simulated length of the loop (s)
 */
public record LoopRecord(int index, boolean caught, double apexHeight, Vec3 landing, double targetHeight,
        ThrowParameters throwParams,
        double maxPenetration, double maxLimitExcess, double peakTorqueRatio, double duration) {
}
