package handsim.config;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.math.Vec3;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A read-only view of one JSON value that knows where it came from. Every accessor validates
 * what it returns and fails with a {@link ConfigException} naming the source, the JSON path of
 * the field and the offending value. Object views remember which fields were read so that
 * {@link #requireNoUnknownFields()} can reject typos.
 */
public final class Json {

    /**
     * Strict: text after the JSON value (a second object, a stray character) is an error too, and
     * so is a key given twice in one object (else the last one would silently win).
     */
    private static final ObjectMapper MAPPER = new ObjectMapper().enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);

    private final String source;
    private final String path;
    private final JsonNode node;
    private final Set<String> read = new LinkedHashSet<>();

    private Json(String source, String path, JsonNode node) {
        this.source = source;
        this.path = path;
        this.node = node;
    }

    /** Parses a file; syntax errors name the file, line and column. */
    public static Json load(Path file) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (java.nio.file.NoSuchFileException e) {
            throw new ConfigException(file + ": no such file");
        } catch (IOException e) {
            String reason = e instanceof java.nio.file.FileSystemException f && f.getReason() != null ? f.getReason() : e.getMessage();
            throw new ConfigException(file + ": cannot read it (" + (Files.isDirectory(file) ? "a folder" : reason) + ")", e);
        }
        ReadLog.record(file, bytes);
        String text;
        try {
            text = java.nio.charset.StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(bytes)).toString();
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new ConfigException(file + ": not a JSON text file (it is not UTF-8)");
        }
        return parse(file.toString(), text);
    }

    /** Parses a file with {@code overrides} applied ({@link #withOverrides}): a run's variant of a config file. */
    public static Json load(Path file, Map<String, String> overrides) {
        Json j = load(file);
        return of(j.source(), withOverrides(j.source(), j.node(), overrides));
    }

    /** Parses JSON text; {@code source} names it in error messages, with the line and column of a syntax error. */
    public static Json parse(String source, String text) {
        try {
            return of(source, MAPPER.readTree(text.startsWith("\ufeff") ? text.substring(1) : text));
        } catch (JsonProcessingException e) {
            String where = e.getLocation() == null ? "" : " at line " + e.getLocation().getLineNr() + ", column "
                    + e.getLocation().getColumnNr();
            throw new ConfigException(source + ": not valid JSON" + where + ": " + plain(e.getOriginalMessage()));
        }
    }

    /** Jackson's message about a syntax error without its internals (character codes, parser features to enable). */
    static String plain(String message) {
        if (message.contains("ALLOW_NON_NUMERIC_NUMBERS")) {
            return message.replaceFirst(":.*", "") + " (NaN and Infinity are not JSON numbers)";
        }
        if (message.startsWith("Duplicate field")) {
            return message.replaceFirst("Duplicate field '(.*)'.*", "the key \"$1\" appears twice in one object (which one is meant?)");
        }
        if (message.contains("ALLOW_COMMENTS")) {
            return "a comment, which JSON does not have (use a \"comment\" field)";
        }
        return message.replaceAll(" \\(code [^)]*\\)", "").replaceAll(":? *enable `.*", "")
                .replaceAll("\\s*\\((for|start marker)[^\n]*\\[Source.*", "").lines().findFirst().orElse("");
    }

    public static Json of(String source, JsonNode node) {
        if (node == null || node.isMissingNode()) {
            throw new ConfigException(source + ": empty document");
        }
        return new Json(source, "", node);
    }

    /** The underlying tree (for copying a config into a run folder). */
    public JsonNode node() {
        return node;
    }

    public String source() {
        return source;
    }

    /** JSON path of this value, e.g. {@code joints[2].axis}; empty for the root. */
    public String path() {
        return path;
    }

    /** A failure about this value. */
    public ConfigException error(String problem) {
        return new ConfigException(source + ": " + (path.isEmpty() ? "(root)" : path) + ": " + problem);
    }

    /** A failure about field {@code name} of this object. */
    public ConfigException fieldError(String name, String problem) {
        return new ConfigException(source + ": " + childPath(name) + ": " + problem);
    }

    private String childPath(String name) {
        return path.isEmpty() ? name : path + "." + name;
    }

    private JsonNode requireObject() {
        if (!node.isObject()) {
            throw error("expected an object, got " + describe(node));
        }
        return node;
    }

    public boolean has(String name) {
        return requireObject().has(name) && !node.get(name).isNull();
    }

    /** A required field. */
    public Json get(String name) {
        JsonNode child = requireObject().get(name);
        read.add(name);
        if (child == null || child.isNull()) {
            throw fieldError(name, "required field is missing");
        }
        return new Json(source, childPath(name), child);
    }

    /** Names of the fields of this object, in file order. */
    public List<String> fieldNames() {
        List<String> names = new ArrayList<>();
        requireObject().fieldNames().forEachRemaining(names::add);
        return names;
    }

    /** Rejects fields that were never read (typos, fields of another schema). */
    public void requireNoUnknownFields() {
        for (Iterator<String> it = requireObject().fieldNames(); it.hasNext(); ) {
            String name = it.next();
            if (!read.contains(name)) {
                throw fieldError(name, "unknown field (known here: " + String.join(", ", read) + ")");
            }
        }
    }

    /** Marks fields as known without reading them (documentation fields such as "comment"). */
    public void allow(String... names) {
        read.addAll(List.of(names));
    }

    public List<Json> elements() {
        if (!node.isArray()) {
            throw error("expected an array, got " + describe(node));
        }
        List<Json> out = new ArrayList<>(node.size());
        for (int i = 0; i < node.size(); i++) {
            out.add(new Json(source, path + "[" + i + "]", node.get(i)));
        }
        return out;
    }

    public List<Json> array(String name) {
        return get(name).elements();
    }

    public String asString() {
        if (!node.isTextual()) {
            throw error("expected a string, got " + describe(node));
        }
        return node.asText();
    }

    public String string(String name) {
        return get(name).asString();
    }

    public String string(String name, String fallback) {
        return has(name) ? string(name) : markRead(name, fallback);
    }

    public boolean bool(String name, boolean fallback) {
        if (!has(name)) {
            return markRead(name, fallback);
        }
        Json v = get(name);
        if (!v.node.isBoolean()) {
            throw v.error("expected true or false, got " + describe(v.node));
        }
        return v.node.asBoolean();
    }

    private <T> T markRead(String name, T value) {
        read.add(name);
        return value;
    }

    public double asNumber() {
        if (!node.isNumber()) {
            throw error("expected a number, got " + describe(node));
        }
        double v = node.asDouble();
        if (!Double.isFinite(v)) {
            throw error("expected a finite number, got " + v);
        }
        return v;
    }

    public double number(String name) {
        return get(name).asNumber();
    }

    public double number(String name, double fallback) {
        return has(name) ? number(name) : markRead(name, fallback);
    }

    /** A required number in the closed interval [min, max]. */
    public double number(String name, double min, double max) {
        double v = number(name);
        if (v < min || v > max) {
            throw fieldError(name, "must be in [" + show(min) + ", " + show(max) + "], got " + show(v));
        }
        return v;
    }

    /** A number as people write it: 100, 0.01, 1E-6, 2.5E+8. */
    public static String show(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e7) {
            return Long.toString((long) v);
        }
        java.math.BigDecimal b = java.math.BigDecimal.valueOf(v).stripTrailingZeros();
        return Math.abs(v) >= 1e-4 && Math.abs(v) < 1e7 ? b.toPlainString() : b.toString();
    }

    /** A required number strictly greater than zero. */
    public double positive(String name) {
        double v = number(name);
        if (!(v > 0)) {
            throw fieldError(name, "must be > 0, got " + v);
        }
        return v;
    }

    public int integer(String name) {
        Json v = get(name);
        if (!v.node.isIntegralNumber()) {
            throw v.error("expected an integer, got " + describe(v.node));
        }
        return v.node.asInt();
    }

    public int integer(String name, int min, int max) {
        int v = integer(name);
        if (v < min || v > max) {
            throw fieldError(name, "must be in [" + min + ", " + max + "], got " + v);
        }
        return v;
    }

    public long longValue(String name) {
        Json v = get(name);
        if (!v.node.isIntegralNumber()) {
            throw v.error("expected an integer, got " + describe(v.node));
        }
        return v.node.asLong();
    }

    public double[] asNumbers(int length) {
        List<Json> items = elements();
        if (length >= 0 && items.size() != length) {
            throw error("expected " + length + " numbers, got " + items.size() + " in " + node);
        }
        double[] out = new double[items.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = items.get(i).asNumber();
        }
        return out;
    }

    public double[] numbers(String name, int length) {
        return get(name).asNumbers(length);
    }

    public Vec3 asVec3() {
        return Vec3.of(asNumbers(3));
    }

    public Vec3 vec3(String name) {
        return get(name).asVec3();
    }

    public Vec3 vec3(String name, Vec3 fallback) {
        return has(name) ? vec3(name) : markRead(name, fallback);
    }

    /** A required two-element [low, high] range with low <= high. */
    public double[] range(String name) {
        Json v = get(name);
        double[] r = v.asNumbers(2);
        if (r[0] > r[1]) {
            throw v.error("range must be [low, high] with low <= high, got [" + r[0] + ", " + r[1] + "]");
        }
        return r;
    }

    /** A required string that must be one of {@code allowed}. */
    public String choice(String name, String... allowed) {
        String v = string(name);
        for (String a : allowed) {
            if (a.equals(v)) {
                return v;
            }
        }
        throw fieldError(name, "must be one of " + String.join(", ", allowed) + ", got \"" + v + "\"");
    }

    private static String describe(JsonNode n) {
        if (n.isTextual()) {
            return "\"" + n.asText() + "\"";
        }
        if (n.isObject()) {
            return "an object";
        }
        if (n.isArray()) {
            return "an array " + n;
        }
        return n.toString();
    }

    // ---- overrides ---------------------------------------------------------------------------

    /**
     * Applies {@code key=value} overrides to a copy of {@code root}. Keys are dotted paths into
     * existing objects ({@code ddpg.actorLr=1e-4}); values are parsed as JSON when they parse and
     * taken as strings otherwise. A key may name a field the file leaves out (an optional one, such
     * as {@code training.criticWarmupDecisions}): the schema's parser, which rejects fields it does
     * not know, then catches a misspelt key, so a typo never silently does nothing. The value
     * {@code null} removes the field: an optional one is then left out, a required one missed.
     */
    public static JsonNode withOverrides(String source, JsonNode root, Map<String, String> overrides) {
        JsonNode copy = root.deepCopy();
        for (Map.Entry<String, String> e : overrides.entrySet()) {
            String[] parts = e.getKey().split("\\.");
            JsonNode parent = copy;
            for (int i = 0; i < parts.length - 1; i++) {
                parent = parent.get(parts[i]);
                if (parent == null || !parent.isObject()) {
                    throw new ConfigException(source + ": overriding " + e.getKey() + ": no object \"" + parts[i] + "\" to set a field in");
                }
            }
            String leaf = parts[parts.length - 1];
            JsonNode value = parseValue(e.getValue());
            if (value.isNull()) {
                ((ObjectNode) parent).remove(leaf); // KEY=null leaves an optional field out
            } else {
                ((ObjectNode) parent).set(leaf, value);
            }
        }
        return copy;
    }

    private static JsonNode parseValue(String text) {
        try {
            return MAPPER.readTree(text);
        } catch (JsonProcessingException notJson) {
            return JsonNodeFactory.instance.textNode(text);
        }
    }

    /** Pretty JSON text of a tree. */
    public static String pretty(JsonNode node) {
        try {
            return MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(node);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A shared mapper for writing result files. */
    public static ObjectMapper mapper() {
        return MAPPER;
    }

    /** Builds an array node of numbers. */
    public static ArrayNode array(double... values) {
        ArrayNode a = JsonNodeFactory.instance.arrayNode();
        for (double v : values) {
            a.add(v);
        }
        return a;
    }
}
