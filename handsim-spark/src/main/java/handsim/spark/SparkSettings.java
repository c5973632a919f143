package handsim.spark;

import handsim.config.Json;

/**
 * The driver's Spark settings, {@code configs/spark.json} (every field is described there).
 *
 * @param executorMemory each executor's heap, in Spark's notation ("2g")
 * @param executorJavaOptions the executors' JVM options
 * @param taskMaxFailures attempts of a call lost with its executor before the run stops
 * @param shipJars true: handsim's classes travel with the job (spark.jars); false: executors read them at the driver's paths
 * @param registrationSeconds how long the driver waits for a first executor, s
 * @param settleSeconds how long no other executor may register before the driver counts them, s
 * @param progressSeconds seconds between progress lines
 */
record SparkSettings(String executorMemory, String executorJavaOptions, int taskMaxFailures, boolean shipJars,
        double registrationSeconds, double settleSeconds, double progressSeconds) {

    static final String FILE = "configs/spark.json";

    static SparkSettings parse(Json j) {
        j.allow("comment", "fields");
        String memory = j.string("executorMemory");
        if (!memory.matches("[0-9]+[kmgt]")) {
            throw j.fieldError("executorMemory", "must be a size like 2g or 1536m, got \"" + memory + "\"");
        }
        SparkSettings s = new SparkSettings(memory, j.string("executorJavaOptions"), j.integer("taskMaxFailures", 1, 100),
                j.choice("code", "classpath", "jars").equals("jars"), j.number("registrationSeconds", 1, 3600),
                j.number("settleSeconds", 0, 60), j.number("progressSeconds", 1, 3600));
        j.requireNoUnknownFields();
        return s;
    }
}
