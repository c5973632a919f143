package handsim.app;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.control.ThrowParameters;
import handsim.learn.ActorPretraining;
import handsim.learn.DdpgAgent;
import handsim.report.Outputs;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.train.ThrowEnvFactory;
import handsim.train.Warmstart;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim warmstart}: the imitation warm start of paper sec. 4.4 — CMA-ES throws for many
 * initial conditions, the successful ones as a dataset, and the actor pretrained on it.
 */
@Command(name = "warmstart", mixinStandardHelpOptions = true,
        description = "For seeded initial conditions (an object caught, a throw to choose) search the throw with CMA-ES "
                + "(commons-math3), keep the successful (state, action) pairs as dataset.csv and pretrain the actor on "
                + "them; writes runs/warmstart__<name>__<seed>__<time>/. Start DDPG from it with "
                + "train --config ... --init-actor RUN_DIR.")
final class WarmstartCommand implements Callable<Integer> {

    @Option(names = "--config", paramLabel = "FILE", required = true,
            description = "warm-start config, e.g. configs/train/flip-warmstart.json")
    Path config;

    @Option(names = "--set", paramLabel = "KEY=VALUE", description = "override a config field, e.g. --set run.workers=1 "
            + "(repeatable; dotted paths into the file)")
    List<String> overrides = List.of();

    @Option(names = "--runs", paramLabel = "DIR", description = "where the run folder goes (default: runs/)")
    Path runs;

    @Mixin
    ClusterOptions cluster;

    @Override
    public Integer call() throws Exception {
        cluster.validate();
        Warmstart.Config c = Warmstart.Config.parse(RunOptions.configFile(config, overrides));
        RunConfigs configs = TrainCommand.configs(c.train().run());
        ThrowEnvFactory envs = TrainCommand.environments(c.train().run(), configs);
        double[] nominal = envs.space().toAction(configs.task(c.train().run().task()).newTask(c.train().run().object()).nominalThrow());
        // a cluster is reached before the run folder is made: a master that cannot be used leaves nothing behind
        Rollouts<Simulator> remote = cluster.remote() ? ClusterWiring.rollouts(cluster, configs, "handsim warmstart "
                + c.train().run().name() + " seed " + c.train().learner().seed()) : null;
        Path dir = ClusterWiring.closingOnFailure(remote, () -> RunFolders.claim(runs, "--runs", "warmstart", c.train().run().name(),
                c.train().learner().seed()));
        Outputs.writeJson(dir.resolve("config.json"), c.toJson());
        TrainCommand.recordSpec(dir, configs);
        Outputs.writeJson(dir.resolve("run.json"),
                RunOptions.provenance(RunOptions.commandLine("warmstart", config, overrides), c.train().learner().seed()));
        System.out.printf(Locale.ROOT, "warm start of the %s task (%s) in %s: CMA-ES over %d initial conditions, %d evaluations "
                + "each at most, on %s%n", c.train().run().task(), c.train().run().object(), dir,
                c.warmstart().initialConditions(), c.train().learner().cmaes().maxEvaluations(),
                cluster.remote() ? "--master " + cluster.master() : c.train().run().workers() + " workers");
        List<Warmstart.Search> searches;
        try (Rollouts<Simulator> rollouts = remote != null ? remote : Wiring.rollouts(configs.model(), configs.sim(), c.train().run().workers())) {
            searches = Warmstart.search(c, envs, nominal, rollouts, cluster.remote() ? PortableWarmstart.shipper(c, configs) : null, System.out);
        }
        ArrayNode all = Json.mapper().createArrayNode();
        for (Warmstart.Search s : searches) {
            ObjectNode o = all.addObject();
            o.put("seed", s.seed());
            o.put("reward", s.reward());
            o.put("evaluations", s.evaluations());
            o.put("kept", s.kept());
            o.set("action", Json.array(s.action()));
            o.set("throw", Json.array(envs.space().fromAction(s.action()).toArray()));
        }
        Outputs.writeJson(dir.resolve("searches.json"), all);
        long kept = searches.stream().filter(Warmstart.Search::kept).count();
        System.out.printf(Locale.ROOT, "%d of %d initial conditions gave a throw with reward >= %.2f%n", kept, searches.size(),
                c.warmstart().keepReward());
        Warmstart.writeDataset(dir.resolve(Warmstart.DATASET), searches);
        double[][][] data = Warmstart.readDataset(dir, envs.observationSize(), ThrowParameters.SIZE);
        ActorPretraining.Result[] fit = new ActorPretraining.Result[1];
        DdpgAgent agent = Warmstart.pretrainedAgent(c.train(), envs.observationSize(), ThrowParameters.SIZE, data, fit);
        Warmstart.plotPretraining(dir.resolve("pretraining.png"), fit[0], "Actor pretraining on " + kept + " CMA-ES throws ("
                + c.train().run().task() + ", " + c.train().run().object() + ")");
        ObjectNode provenance = Json.mapper().createObjectNode();
        provenance.put("warmstart", dir.getFileName().toString());
        provenance.put("examples", kept);
        Warmstart.policyFile(agent, c.train(), envs, provenance).save(dir.resolve("pretrained-policy.json"));
        double[] v = fit[0].validationLoss(), t = fit[0].trainLoss();
        System.out.printf(Locale.ROOT, "pretrained the actor: training loss %.4f -> %.4f, held-out %.4f -> %.4f (%d / %d examples)%n",
                t[0], t[t.length - 1], v[0], v[v.length - 1], fit[0].trainExamples(), fit[0].validationExamples());
        System.out.println("wrote " + dir.resolve(Warmstart.DATASET) + ", searches.json, pretraining.png, pretrained-policy.json");
        return 0;
    }
}
