package handsim.task;

import handsim.math.Vec3;

/** Loop records of scripted throws for tests: flights, arrivals and rests with only the fields a test reads set. */
public final class ScriptedLoops {

    private ScriptedLoops() {
    }

    public static LoopRecord flight(double rotationDeg, boolean caught, Vec3 where) {
        return flight(rotationDeg, caught, where, caught ? 10 : Double.NaN);
    }

    public static LoopRecord flight(double rotationDeg, boolean caught, Vec3 where, double catchTiltDeg) {
        return new LoopRecord(1, caught, 1.3, caught ? null : where, Double.NaN, null, false, Double.NaN,
                Math.toRadians(rotationDeg), Double.NaN, Math.toRadians(catchTiltDeg), Double.NaN,
                caught ? where : null, Double.NaN, 0, 0, 0, 1);
    }


    public static LoopRecord arriving(double arrivalDeg, boolean caught, double catchTiltDeg) {
        return new LoopRecord(1, caught, 1.3, caught ? null : Vec3.ZERO, Double.NaN, null, false, Double.NaN, Math.PI,
                Double.NaN, caught ? Math.toRadians(catchTiltDeg) : Double.NaN, Double.NaN,
                Vec3.ZERO, Math.toRadians(arrivalDeg), 0, 0, 0, 1);
    }

    /** A flip caught and resting {@code tiltDeg} out of the palm's plane, {@code headingDeg} from across it, caught at {@code where}. */
    public static LoopRecord caughtResting(double tiltDeg, double headingDeg, Vec3 where) {
        return new LoopRecord(1, true, 1.3, null, Double.NaN, null, false, Double.NaN, Math.PI, Double.NaN, Math.toRadians(tiltDeg),
                Math.toRadians(headingDeg), where, Double.NaN, 0, 0, 0, 1);
    }

    /** A caught throw-in resting at {@code headingDeg} in the palm (NaN: dropped). */
    public static LoopRecord restingAt(double headingDeg) {
        return new LoopRecord(0, !Double.isNaN(headingDeg), Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, 10, Math.toRadians(headingDeg), null, Double.NaN, 0, 0, 0, 1);
    }
}
