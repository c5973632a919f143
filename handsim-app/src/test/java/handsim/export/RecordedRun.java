package handsim.export;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.sim.Simulator;
import handsim.sim.ode.OdeSimulator;
import handsim.scene.CatchLoopScene;
import handsim.scene.SceneCommand;
import java.util.ArrayList;
import java.util.List;

/**
 * A catch-and-throw loop of the height task with the nominal controller, recorded as the export
 * records it, and beside each sample the simulator's own reading of the joint angles
 * ({@link Simulator#readJoints}) at that instant: what the tests hold an export against.
 */
final class RecordedRun {

    final MotionClip clip;
    /** Per sample, the simulator's joint angles (rad, model DOF order). */
    final List<double[]> jointAngles = new ArrayList<>();

    RecordedRun(String object, long seed, double seconds, double rate) {
        this(object, seed, seconds, rate, Double.NaN);
    }

    /**
     * As above, with a new throw (the next seed's episode: the world reset, an object of another
     * size) at {@code newThrowAt} seconds into the recording (NaN: none).
     */
    RecordedRun(String object, long seed, double seconds, double rate, double newThrowAt) {
        Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig());
        MotionRecorder recorder = new MotionRecorder(rate);
        int samples = recorder.samplesOver(seconds);
        try (CatchLoopScene scene = AppTestSupport.heightLoopScene(sim, object, seed)) {
            boolean thrown = Double.isNaN(newThrowAt);
            while (recorder.sampleCount() < samples) {
                if (!thrown && recorder.sampleCount() >= newThrowAt * rate) {
                    scene.apply(SceneCommand.NEW_THROW);
                    thrown = true;
                }
                scene.advance(recorder.untilNext());
                if (recorder.due(scene.time())) {
                    recorder.record(scene.snapshot(), scene.goal());
                    double[] q = new double[sim.model().dofCount()];
                    sim.readJoints(q, new double[q.length]);
                    jointAngles.add(q);
                }
            }
        }
        clip = recorder.clip("test: height task, " + object + ", nominal controller, seed " + seed);
    }
}
