package handsim.learn;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.report.Outputs;
import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.zip.Deflater;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;
import org.deeplearning4j.nn.multilayer.MultiLayerNetwork;
import org.deeplearning4j.util.ModelSerializer;

/**
 * The whole state of a {@link DdpgAgent} in one zip file: the four networks, six with TD3's
 * twin critics (DL4J {@link ModelSerializer}; actor and critics with their Adam state and step
 * counts), the normaliser's statistics, the replay buffer, the replay generator's state and the
 * update count, plus a caller's JSON ({@link Trainer} puts its own counters and generator there).
 * Written atomically ({@link Outputs}): a run killed while saving keeps its previous
 * checkpoint. After loading, the agent acts and learns exactly as the saved one would have.
 *
 * <pre>
 * state.json        format, sizes, the ddpg config, updates, replay generator, normaliser, extra
 * actor.zip, critic.zip, actorTarget.zip, criticTarget.zip
 * critic2.zip, critic2Target.zip   only with TD3's twin critics
 * replay.bin        the filled part of the ring (DataOutputStream, big-endian doubles)
 * </pre>
 */
public final class Checkpoints {

    public static final String FORMAT = "handsim-ddpg-checkpoint";
    public static final int VERSION = 1;

    /** A loaded checkpoint: the agent and the caller's JSON ({@code null} if none was saved). */
    public record Loaded(DdpgAgent agent, JsonNode extra) {
    }

    private Checkpoints() {
    }

    public static void save(Path file, DdpgAgent agent, JsonNode extra) throws IOException {
        ObjectNode state = Json.mapper().createObjectNode();
        state.put("format", FORMAT);
        state.put("version", VERSION);
        state.put("observationSize", agent.obsSize);
        state.put("actionSize", agent.actionSize);
        state.set("ddpg", Json.mapper().valueToTree(agent.config));
        state.put("updates", agent.updates);
        state.put("replayRng", agent.replayRng.state());
        ObjectNode norm = state.putObject("normalizer");
        norm.put("count", agent.normalizer.count());
        norm.set("mean", Json.array(agent.normalizer.rawMean()));
        norm.set("m2", Json.array(agent.normalizer.rawM2()));
        state.set("extra", extra == null ? NullNode.getInstance() : extra);

        Outputs.write(file, out -> {
            ZipOutputStream zip = new ZipOutputStream(out);
            zip.setLevel(Deflater.BEST_SPEED);
            put(zip, "state.json", Json.pretty(state).getBytes(StandardCharsets.UTF_8));
            put(zip, "actor.zip", networkBytes(agent.actor, true));
            put(zip, "critic.zip", networkBytes(agent.critic, true));
            put(zip, "actorTarget.zip", networkBytes(agent.actorTarget, false));
            put(zip, "criticTarget.zip", networkBytes(agent.criticTarget, false));
            if (agent.critic2 != null) {
                put(zip, "critic2.zip", networkBytes(agent.critic2, true));
                put(zip, "critic2Target.zip", networkBytes(agent.critic2Target, false));
            }
            zip.putNextEntry(new ZipEntry("replay.bin"));
            DataOutputStream data = new DataOutputStream(new BufferedOutputStream(zip, 1 << 16));
            agent.replay.write(data);
            data.flush();
            zip.closeEntry();
            zip.finish();
        });
    }

    /** A checkpoint file that cannot be read back: truncated, not a zip, an entry missing or unreadable. */
    public static final class Damaged extends IOException {
        private static final long serialVersionUID = 1L;

        private final String reason;

        public Damaged(Path file, Exception cause) {
            super(file + " is damaged (" + reason(cause) + ")", cause);
            this.reason = reason(cause);
        }

        /** What is wrong with it, in one line. */
        public String reason() {
            return reason;
        }

        private static String reason(Exception e) {
            String m = e.getMessage() == null || e.getMessage().isBlank() ? e.getClass().getSimpleName() : e.getMessage();
            m = m.lines().findFirst().orElse(m);
            return m.length() > 160 ? m.substring(0, 160) + "..." : m;
        }
    }

    /**
     * The agent and caller's JSON saved in {@code file}; a file that is not a complete, readable
     * checkpoint fails with {@link Damaged}, a missing one with {@link java.nio.file.NoSuchFileException}.
     */
    public static Loaded load(Path file) throws IOException {
        if (!Files.exists(file)) {
            throw new java.nio.file.NoSuchFileException(file.toString());
        }
        try {
            return read(file);
        } catch (IOException | RuntimeException e) {
            throw new Damaged(file, e);
        }
    }

    private static Loaded read(Path file) throws IOException {
        Map<String, byte[]> entries = new HashMap<>();
        try (ZipInputStream zip = new ZipInputStream(Files.newInputStream(file))) {
            for (ZipEntry e; (e = zip.getNextEntry()) != null; ) {
                entries.put(e.getName(), zip.readAllBytes());
            }
        }
        Json state = Json.parse(file + "!state.json", new String(entry(entries, file, "state.json"), StandardCharsets.UTF_8));
        if (!FORMAT.equals(state.string("format"))) {
            throw state.fieldError("format", "expected \"" + FORMAT + "\", got \"" + state.string("format") + "\"");
        }
        state.integer("version", VERSION, VERSION);
        int obsSize = state.integer("observationSize", 1, 1 << 20);
        int actionSize = state.integer("actionSize", 1, 1 << 20);
        LearnerConfig.Ddpg config = LearnerConfig.Ddpg.parse(state.get("ddpg"));
        Json norm = state.get("normalizer");
        Normalizer normalizer = new Normalizer(obsSize, config.normalizeObservations(), config.observationClip(),
                config.observationMinStd());
        normalizer.restore(norm.numbers("mean", obsSize), norm.numbers("m2", obsSize), norm.longValue("count"));
        norm.requireNoUnknownFields();
        boolean twin = config.td3().twinCritics();
        ReplayBuffer replay = ReplayBuffer.read(new DataInputStream(new ByteArrayInputStream(entry(entries, file, "replay.bin"))));
        DdpgAgent agent = new DdpgAgent(config, obsSize, actionSize, network(entries, file, "actor.zip", true),
                network(entries, file, "critic.zip", true), network(entries, file, "actorTarget.zip", false),
                network(entries, file, "criticTarget.zip", false),
                twin ? network(entries, file, "critic2.zip", true) : null,
                twin ? network(entries, file, "critic2Target.zip", false) : null,
                normalizer, replay, new Rng(state.longValue("replayRng")));
        agent.updates = state.longValue("updates");
        JsonNode extra = state.node().get("extra");
        state.allow("extra");
        state.requireNoUnknownFields();
        return new Loaded(agent, extra == null || extra.isNull() ? null : extra);
    }

    private static void put(ZipOutputStream zip, String name, byte[] bytes) throws IOException {
        zip.putNextEntry(new ZipEntry(name));
        zip.write(bytes);
        zip.closeEntry();
    }

    private static byte[] networkBytes(MultiLayerNetwork net, boolean withUpdater) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ModelSerializer.writeModel(net, bytes, withUpdater);
        return bytes.toByteArray();
    }

    private static MultiLayerNetwork network(Map<String, byte[]> entries, Path file, String name, boolean withUpdater)
            throws IOException {
        try (InputStream in = new ByteArrayInputStream(entry(entries, file, name))) {
            return ModelSerializer.restoreMultiLayerNetwork(in, withUpdater);
        }
    }

    private static byte[] entry(Map<String, byte[]> entries, Path file, String name) throws IOException {
        byte[] b = entries.get(name);
        if (b == null) {
            throw new IOException("entry " + name + " is missing");
        }
        return b;
    }
}
