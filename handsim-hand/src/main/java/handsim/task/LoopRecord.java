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
 * @param targetHeight the apex height the loop's throw aimed at (m; NaN for loop 0 and for
 *     tasks without a height goal)
 * @param throwParams the THROW parameters of the loop (null for loop 0)
 * @param boxHit the object touched a static box (the box task's target) during the loop
 * @param boxDistance least distance between the object and a static box during the loop (m;
 *     0 when it touched one, NaN when there is no box)
 * @param flightRotation the net end-over-end turn of the object's long axis (about a horizontal
 *     axis; a flat propeller spin and a wobble add nothing, a turn and its way back cancel) while
 *     the object flew free of the hand, from the release of the throw to the first touch of the
 *     catch (rad, so two turns read 4 pi; NaN for loop 0 and for objects without a long axis)
 * @param releaseSpin how fast the long axis turned end over end as the object left the hand
 *     (rad/s, the same weighting; NaN as for flightRotation): the flight's turn is about this
 *     rate times the flight's duration
 * @param catchTilt how far the object's long axis stood out of the palm's plane when the catch
 *     was judged at the end of MIDDLE (rad: 0 lying in the palm, pi/2 standing on end; NaN when
 *     dropped and for objects without a long axis)
 * @param catchHeading how far the long axis, seen along the palm's normal at that moment, turns
 *     from lying across the palm (the palm's z axis, thumb to little finger) toward its x axis
 *     (toward the fingers): 0 across the palm, pi/2 along the fingers (rad; NaN as catchTilt). The
 *     arm cannot turn the palm under every heading of an arriving object (CatchPlanner), so an
 *     object may come to rest askew
 * @param catchPoint where the object's centre was at the first touch of the catch after the
 *     throw's release (m, world; null for loop 0 and when nothing touched it again)
 * @param arrivalTilt how far the object's long axis stood out of the horizontal at that first
 *     touch (rad: 0 arriving lying, pi/2 end-first; NaN when there was none and for objects
 *     without a long axis): a can arriving end-first is dropped or ends standing in the hand
 * @param maxPenetration deepest hand-object penetration during the loop (m)
 * @param maxLimitExcess largest excursion of any joint beyond its limit (rad)
 * @param peakTorqueRatio largest |tau| / strength of any DOF (1 = at the human limit; PD torques are clamped)
 * @param duration simulated length of the loop (s)
 */
public record LoopRecord(int index, boolean caught, double apexHeight, Vec3 landing, double targetHeight,
        ThrowParameters throwParams, boolean boxHit, double boxDistance, double flightRotation, double releaseSpin, double catchTilt,
        double catchHeading,
        Vec3 catchPoint, double arrivalTilt, double maxPenetration, double maxLimitExcess, double peakTorqueRatio, double duration) {
}
