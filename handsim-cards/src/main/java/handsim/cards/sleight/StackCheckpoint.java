package handsim.cards.sleight;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.SimState;
import handsim.config.ConfigException;
import handsim.config.Json;
import handsim.report.Outputs;
import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

/**
 * A rested card stack kept on disk (thesis 4.2.2: warmed up once, saved, reused by every trial),
 * keyed by the SHA-256 of what it depends on: the configs' fields that shape the warm-up, written
 * canonically (object fields sorted, comments left out). The file holds the key, those fields
 * and the exact {@link SimState}; reading it back gives the state bit for bit, and a file made
 * for other configs is refused, never reused.
 */
public final class StackCheckpoint {

    private static final int MAGIC = 0x48534B31; // "HSK1"

    private StackCheckpoint() {
    }

    /** The key of {@code dependsOn}: SHA-256 of its canonical JSON, in hex. */
    public static String key(JsonNode dependsOn) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(canonical(dependsOn).getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(digest);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** JSON with object fields sorted by name and "comment" fields left out; numbers as Jackson writes them. */
    static String canonical(JsonNode node) {
        if (node.isObject()) {
            List<String> names = new ArrayList<>();
            node.fieldNames().forEachRemaining(names::add);
            names.removeIf(n -> n.equals("comment"));
            names.sort(null);
            StringBuilder b = new StringBuilder("{");
            for (String n : names) {
                b.append(b.length() > 1 ? "," : "").append(Json.mapper().getNodeFactory().textNode(n)).append(':').append(canonical(node.get(n)));
            }
            return b.append('}').toString();
        }
        if (node.isArray()) {
            StringBuilder b = new StringBuilder("[");
            for (int i = 0; i < node.size(); i++) {
                b.append(i > 0 ? "," : "").append(canonical(node.get(i)));
            }
            return b.append(']').toString();
        }
        return node.toString();
    }

    /** Writes {@code state} for the configs {@code dependsOn} to {@code file} (atomically). */
    public static void write(Path file, JsonNode dependsOn, SimState state) throws IOException {
        String key = key(dependsOn);
        String fields = canonical(dependsOn);
        Outputs.write(file, out -> {
            DataOutputStream data = new DataOutputStream(out);
            data.writeInt(MAGIC);
            data.writeUTF(key);
            byte[] text = fields.getBytes(StandardCharsets.UTF_8);
            data.writeInt(text.length);
            data.write(text);
            state.write(data);
            data.flush();
        });
    }

    /**
     * Reads the state in {@code file}, which must have been made for the configs {@code
     * dependsOn}; a file made for others is refused with a {@link ConfigException} naming both
     * keys.
     */
    public static SimState read(Path file, JsonNode dependsOn) throws IOException {
        String want = key(dependsOn);
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file))) {
            DataInputStream data = new DataInputStream(in);
            if (data.readInt() != MAGIC) {
                throw new ConfigException(file + ": not a card-stack checkpoint");
            }
            String key = data.readUTF();
            if (!key.equals(want)) {
                throw new ConfigException(file + ": a stale checkpoint: made for configs of key " + key.substring(0, 16)
                        + "..., these have " + want.substring(0, 16) + "... (delete it, or use the configs it was made for)");
            }
            data.readNBytes(data.readInt());
            return SimState.read(data);
        }
    }

    /** The file for the configs {@code dependsOn} in {@code dir}: {@code NAME-KEY16.bin}. */
    public static Path file(Path dir, String name, JsonNode dependsOn) {
        return dir.resolve(name + "-" + key(dependsOn).substring(0, 16) + ".bin");
    }

    /** The fields of a Double Lift scene's configs that shape its rested stack. */
    static ObjectNode dependsOn(SleightFiles files, String cardPreset) {
        ObjectNode o = Json.mapper().createObjectNode();
        o.put("format", "handsim rested card stack 1");
        o.set("card", files.scene().get("card").node().deepCopy());
        ObjectNode stack = files.scene().get("stack").node().deepCopy();
        stack.remove("freeCards"); // which cards move in a trial does not change the warm-up
        o.set("stack", stack);
        o.set("cardMaterial", files.materials().get("cards").get(cardPreset).node().deepCopy());
        ObjectNode solver = files.solver().node().deepCopy();
        solver.remove("parallel"); // bit-identical either way
        solver.remove("fields");
        o.set("solver", solver);
        return o;
    }
}
