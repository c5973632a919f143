package handsim.task;

import handsim.kin.Frame;
import handsim.math.Vec3;

/**
 * How a long object lies in the hand: its long axis's tilt out of the palm's plane and its
 * heading in it ({@link LoopRecord#catchTilt}, {@link LoopRecord#catchHeading}), both in [0, pi/2].
 */
public record LyingPose(double tilt, double heading) {

    /** The pose of a long axis (unit, world frame) in the palm's frame (y: its normal, z: across it). */
    public static LyingPose of(Frame palm, Vec3 axis) {
        double tilt = Math.asin(Math.min(1, Math.abs(axis.dot(palm.rotation().yAxis()))));
        Vec3 inPalm = palm.rotation().inverseRotate(axis);
        return new LyingPose(tilt, Math.atan2(Math.abs(inPalm.x()), Math.abs(inPalm.z())));
    }
}
