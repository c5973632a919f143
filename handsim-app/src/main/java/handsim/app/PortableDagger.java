package handsim.app;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.config.ConfigSet;
import handsim.config.Json;
import handsim.learn.Dagger;
import handsim.learn.DaggerEpisodes;
import handsim.learn.Policy;
import handsim.rollout.PortableTask;
import handsim.rollout.RolloutTask;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.train.DaggerRun;
import handsim.train.DaggerRunConfig;
import handsim.train.TeachableThrowEnv;
import handsim.train.ThrowEnvFactory;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

/**
 * A DAgger round's episodes in the form that travels to a cluster: the run's config (its
 * config.json) and configuration documents as read, the lead-in policies' bytes, the learner
 * (its policy as JSON, or none for the nominal throw) and each episode's request (round, index,
 * seeds, cut-off). An executor rebuilds the environments and the twin-world teacher from them
 * alone and plays the episodes by index; each comes back as JSON ({@link DaggerEpisodes}).
 *
 * @param config the run's config.json
 * @param documents the run's configuration documents as read ({@link ConfigSet#toJson})
 * @param leadIn the bytes of learnerThrows.leadIn (null without learnerThrows), leadInOpening's (null without)
 * @param actor the learner's policy as JSON, or null for the task's nominal throw
 * @param requests each episode's round, index, environment seed, label seed, cut-off and whether it executes labels
 */
record PortableDagger(String config, String documents, byte[] leadIn, byte[] leadInOpening, String actor, long[][] requests)
        implements PortableTask<Simulator> {

    private static final long serialVersionUID = 1L;

    /** Each worker simulator's twin for the teacher, made once and kept for the later rounds. */
    private static final Map<Simulator, Simulator> TWINS = Collections.synchronizedMap(new IdentityHashMap<>());

    /** What ships each round of the run in {@code dir}, read with {@code configs}. */
    static DaggerRun.Shipper shipper(Path dir, RunConfigs configs) {
        return (round, actor, requests, learnerThrows) -> {
            try {
                return new PortableDagger(Files.readString(dir.resolve(DaggerRun.CONFIG)), configs.files().toJson().toString(),
                        learnerThrows == null ? null : Files.readAllBytes(learnerThrows.leadIn()),
                        learnerThrows == null || learnerThrows.leadInOpening() == null ? null : Files.readAllBytes(learnerThrows.leadInOpening()),
                        actor == null ? null : actor.toJson().toString(), requests.stream().map(r -> new long[] {r.round(), r.episode(),
                                r.envSeed(), r.labelSeed(), r.maxDecisions(), r.executeLabel() ? 1 : 0}).toArray(long[][]::new));
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read what a DAgger round ships", e);
            }
        };
    }

    @Override
    public RolloutTask<Simulator, JsonNode> rebuild() {
        DaggerRunConfig c = DaggerRunConfig.parse(Json.parse("the DAgger run's config", config));
        RunConfigs configs = new RunConfigs(ConfigSet.replaying(Json.parse("the DAgger run's documents", documents)));
        ThrowEnvFactory envs = TrainCommand.environments(c.run(), configs);
        DaggerRunConfig.LearnerThrows t = c.learnerThrows();
        DaggerRunConfig.LearnerThrows throwsOf = t == null ? null : new DaggerRunConfig.LearnerThrows(t.rest(), CachedFiles.of(leadIn),
                leadInOpening == null ? null : CachedFiles.of(leadInOpening), t.maxLoops());
        Function<double[], double[]> learner = actor == null ? DaggerRun.nominalActor(envs) : Policy.parse(Json.parse("the learner", actor))::act;
        return sim -> {
            TeachableThrowEnv env = DaggerRun.teachableEnv(c, throwsOf, envs, sim, TWINS.computeIfAbsent(sim, Wiring::twinSimulator));
            return i -> DaggerEpisodes.toJson(Dagger.play(env, request(i), learner));
        };
    }

    private Dagger.Request request(int i) {
        long[] r = requests[i];
        return new Dagger.Request((int) r[0], (int) r[1], r[2], r[3], (int) r[4], r[5] == 1);
    }

    @Override
    public String what() {
        return requests.length == 0 ? "DAgger episodes" : "DAgger episodes of round " + requests[0][0];
    }

    @Override
    public String label(int index) {
        return String.format(Locale.ROOT, "episode %d of DAgger round %d (seed %d)", requests[index][1], requests[index][0], requests[index][2]);
    }
}
