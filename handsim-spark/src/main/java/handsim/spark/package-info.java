/**
 * Apache Spark as the cluster engine of handsim's portable calls ({@code handsim.rollout}): each
 * call a one-task job on a free executor core, results back as each finishes, a task lost with its
 * executor run again, progress and failure lines on the driver. Found by ServiceLoader when a
 * command is given {@code --master}; Spark itself is {@code provided}, on the classpath only
 * then (the launcher adds it) or under {@code spark-submit}.
 *
 * <p>Imports {@code handsim.config}, {@code handsim.report} and {@code handsim.rollout}, Spark and the JDK; nothing of the
 * hand's or the cards' packages: what runs is described by the calls themselves.
 */
package handsim.spark;
