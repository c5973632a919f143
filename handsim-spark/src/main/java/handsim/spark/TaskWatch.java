package handsim.spark;

import java.io.PrintStream;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.apache.spark.Success$;
import org.apache.spark.TaskEndReason;
import org.apache.spark.TaskFailedReason;
import org.apache.spark.TaskKilled;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerJobStart;
import org.apache.spark.scheduler.SparkListenerTaskEnd;
import org.apache.spark.scheduler.TaskInfo;
import scala.jdk.javaapi.CollectionConverters;

/**
 * Watches the cluster's task attempts: an attempt that failed (its executor lost, killed, out of
 * memory) is said in one line naming the call (its label: number and seed), the executor and
 * the time it had run; the batch of the call counts it and the executor time lost.
 */
final class TaskWatch extends SparkListener {

    /**
     * A batch's failed attempts and the executor time they had run, ms; and its successful tasks'
     * time on their executors, from launch to end, ms (what a call costs beyond its own time there).
     */
    static final class Losses {
        final AtomicInteger attempts = new AtomicInteger();
        final AtomicLong millis = new AtomicLong();
        final AtomicInteger succeeded = new AtomicInteger();
        final AtomicLong taskMillis = new AtomicLong();
    }

    private record Call(String group, String label) {
    }

    private final PrintStream out;
    private final Map<Integer, Call> stages = new ConcurrentHashMap<>();
    private final Map<String, Losses> byGroup = new ConcurrentHashMap<>();

    TaskWatch(PrintStream out) {
        this.out = out;
    }

    Losses losses(String group) {
        return byGroup.computeIfAbsent(group, g -> new Losses());
    }

    @Override
    public void onJobStart(SparkListenerJobStart job) {
        String group = job.properties() == null ? null : job.properties().getProperty("spark.jobGroup.id");
        String label = job.properties() == null ? null : job.properties().getProperty("spark.job.description");
        for (Object stage : CollectionConverters.asJava(job.stageIds())) {
            stages.put((Integer) stage, new Call(group == null ? "" : group, label == null ? "a call" : label));
        }
    }

    @Override
    public void onTaskEnd(SparkListenerTaskEnd end) {
        TaskEndReason reason = end.reason();
        Call call = stages.getOrDefault(end.stageId(), new Call("", "a call"));
        TaskInfo info = end.taskInfo();
        long ms = Math.max(0, info.finishTime() - info.launchTime());
        Losses l = losses(call.group());
        if (reason instanceof Success$) {
            l.succeeded.incrementAndGet();
            l.taskMillis.addAndGet(ms);
            return;
        }
        if (reason instanceof TaskKilled || !(reason instanceof TaskFailedReason failed)) {
            return; // a cancellation the driver asked for
        }
        l.attempts.incrementAndGet();
        l.millis.addAndGet(ms);
        String why = failed.toErrorString().lines().findFirst().orElse("").trim();
        out.printf(Locale.ROOT, "spark: %s: attempt %d failed on executor %s (%s) after %.1f s: %s; %s%n", call.label(),
                info.attemptNumber() + 1, info.executorId(), info.host(), ms / 1000.0, why,
                failed.countTowardsTaskFailures() ? "it runs again if attempts are left" : "it runs again (not counted as a failure of the call)");
        out.flush();
    }
}
