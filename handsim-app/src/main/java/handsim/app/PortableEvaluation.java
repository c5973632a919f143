package handsim.app;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.evaluation.TaskEvaluation;
import handsim.rollout.PortableTask;
import handsim.rollout.RecordedTask;
import handsim.rollout.RolloutTask;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.taskdef.TaskDefinitions;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * An {@code evaluate} run's episodes (or box tests) in the form that travels to a cluster: the
 * run's spec (its record: options, every configuration document as read, the goals, each policy
 * by path and SHA-256, {@link EvaluateSpec}) and the policies' bytes. An executor rebuilds the
 * evaluation from them alone, as {@code evaluate --spec} does, with the policies written to a
 * cache of its own under their SHA-256, and runs its rollouts by index; results travel as the
 * JSON the episode journal keeps. An evaluation makes one run of rollouts: the executor takes
 * the rebuilt evaluation's run by handing it rollouts that keep the task and stop it there.
 *
 * @param spec the run's spec, JSON text
 * @param policies the bytes of each policy file by role (policy, opening_policy, rest_policy)
 */
record PortableEvaluation(String spec, LinkedHashMap<String, byte[]> policies) implements PortableTask<Simulator> {

    private static final long serialVersionUID = 1L;

    /** The run of {@code run}, its policies read now. */
    static PortableEvaluation of(EvaluateSpec run) throws IOException {
        LinkedHashMap<String, byte[]> bytes = new LinkedHashMap<>();
        for (var e : run.policies().entrySet()) {
            bytes.put(e.getKey(), Files.readAllBytes(e.getValue()));
        }
        return new PortableEvaluation(run.toJson().toString(), bytes);
    }

    @Override
    public RolloutTask<Simulator, JsonNode> rebuild() {
        EvaluateSpec run = EvaluateSpec.of(Json.of("the run's spec", withCachedPolicies()));
        TaskEvaluation evaluation = run.definition().evaluation(run.request(null, null, false),
                run.setup(null, new PrintStream(OutputStream.nullOutputStream())));
        RecordedTask<Simulator, Object> task = TaskCapture.firstRun(evaluation);
        return worker -> {
            RolloutTask.Rollout<Object> rollout = task.prepare(worker);
            return i -> task.write().apply(rollout.run(i));
        };
    }

    /** The spec with each policy's path that of its bytes in this JVM's cache (the SHA-256 recorded is checked on reading). */
    private ObjectNode withCachedPolicies() {
        ObjectNode s = (ObjectNode) Json.parse("the run's spec", spec).node();
        if (s.has("policies")) {
            ObjectNode p = (ObjectNode) s.get("policies");
            for (var e : policies.entrySet()) {
                ObjectNode role = (ObjectNode) p.get(e.getKey());
                role.put("file", CachedFiles.of(e.getValue()).toString());
            }
        }
        return s;
    }

    private Json specJson() {
        return Json.parse("the run's spec", spec);
    }

    @Override
    public String what() {
        Json s = specJson();
        return TaskDefinitions.evaluatesTests(s.string("task")) ? "box tests" : s.has("copies") ? "copies of episodes" : "episodes";
    }

    @Override
    public String label(int index) {
        Json s = specJson();
        long seed = s.longValue("seed");
        if (TaskDefinitions.evaluatesTests(s.string("task"))) {
            return "box test " + index + " (seed " + (seed + index) + ")";
        }
        if (s.has("copies")) {
            int copies = s.integer("copies");
            return "copy " + index % copies + " of episode " + index / copies + " (seed " + (seed + index / copies) + ")";
        }
        return "episode " + index + " (seed " + (seed + index) + ")";
    }

    /** Rollouts that keep the task of the first run they are given and stop the caller there. */
    private static final class TaskCapture implements Rollouts<Simulator> {

        private RecordedTask<?, ?> task;

        /** The task of {@code evaluation}'s run of rollouts, its results with their JSON form. */
        @SuppressWarnings("unchecked")
        static RecordedTask<Simulator, Object> firstRun(TaskEvaluation evaluation) {
            TaskCapture capture = new TaskCapture();
            try {
                evaluation.run(capture, Json.mapper().createObjectNode());
            } catch (Taken taken) {
                return (RecordedTask<Simulator, Object>) capture.task;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            throw new IllegalStateException("the evaluation made no run of rollouts");
        }

        /** Stops the evaluation at its run of rollouts, once the task is kept. */
        private static final class Taken extends RuntimeException {
            private static final long serialVersionUID = 1L;

            Taken() {
                super(null, null, false, false);
            }
        }

        @Override
        public int workers() {
            return 1;
        }

        @Override
        public <R> List<R> run(int count, RolloutTask<Simulator, R> run, Listener<? super R> listener) {
            if (!(run instanceof RecordedTask<Simulator, R> recorded)) {
                throw new IllegalStateException("an evaluation's rollouts have no JSON form (" + run.getClass().getName() + ")");
            }
            task = recorded;
            throw new Taken();
        }

        @Override
        public void close() {
        }
    }
}
