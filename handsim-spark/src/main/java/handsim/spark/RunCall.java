package handsim.spark;

import handsim.rollout.PortableCall;
import handsim.rollout.RemoteFailure;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import org.apache.spark.SparkEnv;
import org.apache.spark.api.java.function.Function;

/** Runs a call on an executor and times it; an exception it throws comes back as its result. */
final class RunCall implements Function<PortableCall<?>, Timed> {

    private static final long serialVersionUID = 1L;

    static final RunCall INSTANCE = new RunCall();

    @Override
    public Timed call(PortableCall<?> call) {
        long t0 = System.nanoTime();
        Serializable value;
        try {
            value = call.call();
        } catch (Exception e) {
            return new Timed(null, sendable(e), System.nanoTime() - t0, executor());
        }
        return new Timed(value, null, System.nanoTime() - t0, executor());
    }

    private static String executor() {
        SparkEnv env = SparkEnv.get();
        return env == null ? "?" : env.executorId();
    }

    /** {@code e} if it serialises, else a {@link RemoteFailure} with its message. */
    private static Throwable sendable(Exception e) {
        try (ObjectOutputStream out = new ObjectOutputStream(new ByteArrayOutputStream())) {
            out.writeObject(e);
            return e;
        } catch (IOException notSerialisable) {
            return new RemoteFailure(e.toString());
        }
    }
}
