package handsim.task;


import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.Simulator;

/**
 * The foundation's benchmark and smoke scenario: the arm holds the neutral pose with the hand
 * open, a ball is thrown into the palm on a ballistic arc, and at the first hand-ball contact
 * the fingers close toward the closed pose over {@code closeTime} seconds and hold it, by
 * contact and friction alone.
 */
public final class HeldBallScenario {

    /** Where the throw starts, relative to the palm centre (m, world). */
    public static final Vec3 LAUNCH_OFFSET = new Vec3(0.0, 0.10, 0.06);
    /** Flight time of the throw (s). */
    public static final double FLIGHT_TIME = 0.30;

    private final ServoLoop loop;
    private final double[] open;
    private final double[] closed;
    private final double closeTime;
    private double contactTime = Double.NaN;

    /**
     * Resets the world with the arm in the neutral pose and the hand open, and throws
     * {@code ball} so that it arrives just above the palm centre after {@link #FLIGHT_TIME}.
     */
    public HeldBallScenario(ServoLoop loop, ObjectSpec ball, double closeTime, long seed) {
        this.loop = loop;
        this.closeTime = closeTime;
        Simulator sim = loop.sim();
        HandModel m = sim.model();
        open = m.poseVector("neutral");
        m.pose("open").applyTo(open);
        closed = m.poseVector("neutral");
        m.pose("closed").applyTo(closed);
        sim.reset(open, seed);
        System.arraycopy(open, 0, loop.targets(), 0, open.length);
        Site palm = m.site("palm_center");
        Frame palmFrame = new Kinematics(m).siteFrame(palm, open);
        Vec3 palmUp = palmFrame.rotation().yAxis().negate();
        Vec3 arrival = palmFrame.origin().plus(palmUp.times(ball.halfThickness() + 0.005));
        sim.spawnObject(ball, LaunchDistribution.ballisticLaunch(arrival.plus(LAUNCH_OFFSET), arrival, FLIGHT_TIME, sim.config().gravity()));
    }

    /** Advances one physics step; closes the hand after the first contact. */
    public void step() {
        Simulator sim = loop.sim();
        if (Double.isNaN(contactTime) && sim.handContacts().any()) {
            contactTime = sim.time();
        }
        if (!Double.isNaN(contactTime)) {
            double w = Math.min(1, (sim.time() - contactTime) / closeTime);
            double[] t = loop.targets();
            for (int i = 0; i < t.length; i++) {
                t[i] = open[i] + w * (closed[i] - open[i]);
            }
        }
        loop.step();
    }

    /** Time of the first hand-ball contact, NaN before it. */
    public double contactTime() {
        return contactTime;
    }

    public ServoLoop loop() {
        return loop;
    }
}
