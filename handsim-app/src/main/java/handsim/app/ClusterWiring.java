package handsim.app;

import handsim.rollout.RemoteCalls;
import handsim.rollout.RemoteRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import java.io.IOException;

/**
 * The commands' work on a cluster ({@code --master}): rollouts whose worker simulators and tasks
 * travel as their configuration documents, as {@link Wiring#rollouts} gives the thread pool's.
 */
final class ClusterWiring {

    private ClusterWiring() {
    }

    /** An evaluation's rollouts on the cluster of {@code cluster}: the run's spec is what travels. */
    static Rollouts<Simulator> evaluation(ClusterOptions cluster, EvaluateSpec run) throws IOException {
        run.configs().sim(); // every document the executors need read, so the spec records it
        PortableEvaluation portable = PortableEvaluation.of(run);
        PortableSimulator simulator = PortableSimulator.of(run.configs());
        RemoteCalls calls = cluster.connect("handsim evaluate " + run.task() + " " + run.object() + " seed " + run.seed());
        return new RemoteRollouts<>(calls, simulator, ordinal -> {
            if (ordinal > 0) {
                throw new IllegalStateException("an evaluation makes one run of rollouts, not " + (ordinal + 1));
            }
            return portable;
        });
    }

    /** Rollouts on the cluster of {@code cluster} whose tasks carry their portable forms; workers simulate {@code configs}' model and physics. */
    static Rollouts<Simulator> rollouts(ClusterOptions cluster, RunConfigs configs, String application) {
        PortableSimulator simulator = PortableSimulator.of(configs);
        return new RemoteRollouts<>(cluster.connect(application), simulator, null);
    }

    /** {@code step}'s result; if it fails, {@code remote} (when not null) is closed first, its cluster application ended. */
    static <T> T closingOnFailure(Rollouts<?> remote, java.util.function.Supplier<T> step) {
        try {
            return step.get();
        } catch (RuntimeException e) {
            if (remote != null) {
                remote.close();
            }
            throw e;
        }
    }
}
