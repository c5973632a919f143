package handsim.cards;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.stream.StreamSupport;

/** The IPC Toolkit 1.6.1 reference values in src/test/resources/ipc-oracle.json. */
public final class IpcOracle {

    private static JsonNode cases;

    private IpcOracle() {
    }

    public static synchronized List<JsonNode> cases(String name) {
        if (cases == null) {
            try (InputStream in = IpcOracle.class.getResourceAsStream("/ipc-oracle.json")) {
                cases = new ObjectMapper().readTree(in).get("cases");
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return StreamSupport.stream(cases.get(name).spliterator(), false).toList();
    }

    /** Numbers of a flat array, or of an array of arrays concatenated. */
    public static double[] numbers(JsonNode node) {
        return StreamSupport.stream(node.spliterator(), false)
                .flatMapToDouble(n -> n.isArray() ? java.util.Arrays.stream(numbers(n)) : java.util.stream.DoubleStream.of(n.asDouble()))
                .toArray();
    }

    /** Concatenated positions of the named fields of a case. */
    public static double[] stack(JsonNode c, String... fields) {
        double[] out = new double[3 * fields.length];
        for (int i = 0; i < fields.length; i++) {
            System.arraycopy(numbers(c.get(fields[i])), 0, out, 3 * i, 3);
        }
        return out;
    }
}
