package handsim.scene;

import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A scene without physics for testing pacing: it advances in whole ticks of {@link #TICK}
 * seconds, as the catch loop advances in controller periods, and records the commands it gets.
 */
public final class FakeScene implements InteractiveScene {

    public static final double TICK = 0.002;

    public final List<SceneCommand> commands = new ArrayList<>();
    public RuntimeException failNextAdvance;
    public boolean closed;
    private long ticks;

    @Override
    public void advance(double seconds) {
        if (failNextAdvance != null) {
            RuntimeException e = failNextAdvance;
            failNextAdvance = null;
            throw e;
        }
        double until = time() + seconds;
        while (time() < until - 1e-12) {
            ticks++;
        }
    }

    @Override
    public double time() {
        return ticks * TICK;
    }

    @Override
    public WorldSnapshot snapshot() {
        var model = TestSupport.model();
        return new WorldSnapshot(model, time(), Collections.nCopies(model.bodyCount(), Frame.IDENTITY), Optional.empty(),
                Optional.empty(), List.of(), 0);
    }

    @Override
    public Map<String, String> status() {
        return Map.of("t", Double.toString(time()));
    }

    @Override
    public Goal goal() {
        return new Goal.None();
    }

    /** RESET goes back to time 0; every command is recorded. */
    @Override
    public String apply(SceneCommand command) {
        commands.add(command);
        if (command == SceneCommand.RESET) {
            ticks = 0;
        }
        return "did " + command;
    }

    @Override
    public void close() {
        closed = true;
    }
}
