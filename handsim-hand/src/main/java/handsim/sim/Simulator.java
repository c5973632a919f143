package handsim.sim;

import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.model.HandModel;

/**
 * A physics world holding the arm+hand (fixed shoulder), at most one thrown object, the ground
 * and optional static boxes. Joint state is in the model's DOF order; angles follow {@link
 * handsim.kin.Kinematics}. Methods that fill arrays write into caller-owned buffers so that the
 * per-step path need not allocate.
 */
public interface Simulator extends AutoCloseable {

    HandModel model();

    SimConfig config();

    /** Simulated time in seconds since the last {@link #reset}. */
    double time();

    /** Physics steps since the last {@link #reset}. */
    long stepCount();

    /**
     * Puts the arm at joint angles {@code q} with zero velocity, removes the object and any boxes,
     * clears the contact record and reseeds the engine's random generator: the world is then a
     * function of ({@code q}, {@code seed}) alone.
     */
    void reset(double[] q, long seed);

    /** Joint angles (rad) and rates (rad/s) of the arm+hand. */
    void readJoints(double[] q, double[] qd);

    /**
     * Sets the joint torques (N m, one per DOF) applied, equal and opposite on the joint's two
     * bodies, during the following steps until changed.
     */
    void setJointTorques(double[] tau);

    /** Advances the world by one time step. Throws {@link SimulationDiverged} on NaN or blow-up. */
    void step();

    /** World frame of body {@code body} (origin at its joint anchor). */
    Frame bodyFrame(int body);

    /** World velocity of a point fixed on body {@code body}, given in the body frame. */
    Vec3 pointVelocity(int body, Vec3 local);

    /** Angular velocity (world) of body {@code body}. */
    Vec3 angularVelocity(int body);

    /** Places a new object (replacing any previous one). */
    void spawnObject(ObjectSpec spec, RigidState state);

    boolean hasObject();

    ObjectSpec objectSpec();

    RigidState objectState();

    /**
     * The object's centre of mass (m, world) written to {@code out[0..2]}: what the episode reads
     * every physics step, so implementations should not allocate here (this default does).
     */
    default void objectPosition(double[] out) {
        objectState().position().into(out, 0);
    }

    /** The whole state of the world now, to go on from later or in a twin world ({@link #restoreState}). */
    WorldState captureState();

    /**
     * Puts the world in {@code state}, captured from this simulator or from another of the same
     * model and config: the arm, the object (spawned anew), the boxes, the torques, the clock and
     * the engine's random generator. The world then steps on exactly as the one it was captured
     * from. The contact record starts empty.
     */
    void restoreState(WorldState state);

    /** Adds a fixed box (the target of the box task); it collides with the object only. */
    void addStaticBox(Vec3 center, Vec3 size);

    /** Contacts of the last step between the hand/arm and the object. */
    ContactReport handContacts();

    /** True when the object touched the ground during the last step. */
    boolean objectTouchesGround();

    /** True when the object touched a static box during the last step. */
    boolean objectTouchesBox();

    /** The static boxes added since the last reset. */
    java.util.List<WorldSnapshot.StaticBox> staticBoxes();

    /**
     * Turns on or off accounting of what {@link #step()} costs: its wall time split into
     * collision and solver, and the bytes the engine itself allocates (see {@link
     * StepAccounting}). It costs a few clock and counter reads per step.
     */
    default void setAccounting(boolean on) {
    }

    /** The accounting so far (live; copy to keep), or null if this simulator does not account. */
    default StepAccounting accounting() {
        return null;
    }

    /** A drawable copy of the current state. */
    default WorldSnapshot snapshot() {
        java.util.List<Frame> frames = new java.util.ArrayList<>();
        for (int b = 0; b < model().bodyCount(); b++) {
            frames.add(bodyFrame(b));
        }
        return new WorldSnapshot(model(), time(), frames,
                hasObject() ? java.util.Optional.of(objectSpec()) : java.util.Optional.empty(),
                hasObject() ? java.util.Optional.of(objectState()) : java.util.Optional.empty(),
                staticBoxes(), config().groundHeight());
    }

    @Override
    void close();
}
