package handsim.scene;

import handsim.sim.WorldSnapshot;
import java.util.Map;

/**
 * Something that runs in simulated time and can be looked at: the renderer, the viewer and
 * {@code demo} drive a scene and draw its snapshots; the scene never knows who is watching.
 */
public interface Scene extends AutoCloseable {

    /** Advances the simulation by whole physics steps until at least {@code seconds} have passed. */
    void advance(double seconds);

    /** Simulated time (s). */
    double time();

    /** The world as it is now. */
    WorldSnapshot snapshot();

    /** Short labelled figures for a heads-up display (e.g. state, loop count), in display order. */
    Map<String, String> status();

    @Override
    void close();
}
