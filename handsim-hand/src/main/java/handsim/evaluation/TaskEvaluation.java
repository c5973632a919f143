package handsim.evaluation;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.math.Vec3;
import handsim.report.Outputs;
import handsim.rollout.RecordedTask;
import handsim.rollout.RolloutTask;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.task.ThrowTask;
import java.io.IOException;
import java.io.PrintStream;
import java.util.Locale;
import java.util.function.Function;

/**
 * One kind of evaluation run: its episodes spread over the rollout workers, then its summary in
 * the JSON, the console, the CSV and the chart. A task's definition ({@code handsim.taskdef})
 * picks the kind a request asks for.
 */
public abstract class TaskEvaluation {

    protected final EvaluationRequest request;
    protected final EvaluationSetup setup;
    protected final PrintStream console;

    protected TaskEvaluation(EvaluationRequest request, EvaluationSetup setup) {
        this.request = request;
        this.setup = setup;
        this.console = setup.console();
    }

    /** Runs the episodes on {@code rollouts} and puts the summary into {@code out}. */
    public abstract void run(Rollouts<Simulator> rollouts, ObjectNode out) throws IOException;

    /** A worker's evaluation: its own task (goals are per-episode state) and throw policy. */
    protected CatchEvaluation evaluation(ThrowTask task) {
        return new CatchEvaluation(setup.controller(), setup.limits(), setup.launches(), setup.object(), task,
                setup.policies().apply(task)).watchedBy(setup.watcher());
    }

    /** A progress line with the time left every configs/episode.json progressEveryLoops loops of an episode. */
    protected CatchEvaluation.LoopListener longEpisodeProgress() {
        return new LongEpisodeProgress(console, setup.limits().progressEveryLoops(), request.loops());
    }

    /**
     * {@code task} that reads an episode back from the journal when a killed run of the same
     * command finished it, and otherwise runs it and journals its result at once (without a
     * journal, {@code task} itself); its results' JSON form is also how they travel from a cluster.
     */
    protected <R> RecordedTask<Simulator, R> resumable(RolloutTask<Simulator, R> task, Function<R, JsonNode> write, Function<JsonNode, R> read) {
        return setup.journal() == null ? new RecordedTask<>(task, write, read, null) : setup.journal().resumable(task, write, read);
    }

    /** Writes the CSV file, if one was asked for. */
    protected void writeCsv(CharSequence rows) throws IOException {
        if (request.csv() != null) {
            Outputs.writeString(request.csv(), rows.toString());
            console.println("wrote " + request.csv());
        }
    }

    protected static String csvNumber(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.4f", v);
    }

    protected static String csvPoint(Vec3 p) {
        return p == null ? ",," : csvNumber(p.x()) + "," + csvNumber(p.y()) + "," + csvNumber(p.z());
    }

    /** JSON has no NaN: a figure that could not be measured is null. */
    protected static void putFinite(ObjectNode o, String key, double v) {
        if (Double.isFinite(v)) {
            o.put(key, v);
        } else {
            o.putNull(key);
        }
    }
}
