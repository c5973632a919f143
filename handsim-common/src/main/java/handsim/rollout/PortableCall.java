package handsim.rollout;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * A piece of work that runs in whichever JVM a cluster gives it: it holds serialisable data only
 * (configuration documents as JSON text, seeds, parameters, never a simulator or a lambda that
 * holds one), rebuilds what it needs where it runs, and is a pure function of its data, so a
 * call run twice (a retry after a lost executor) returns equal results.
 *
 * @param <R> what it returns: serialisable
 */
public interface PortableCall<R extends Serializable> extends Serializable {

    /** Runs the work in this JVM. */
    R call() throws Exception;

    /** The call in a few words for progress and failure lines, naming its number and seed: {@code "trial 7 (study seed 5)"}. */
    String label();

    /**
     * The SHA-256 of {@code o}'s serialised form, in hex: sent with a description (a task, an
     * objective, a resource) so that an executor builds what it describes once and keeps it.
     */
    static String key(Serializable o) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(o);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot serialise " + o.getClass().getName() + " to send it to a cluster", e);
        }
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes.toByteArray()));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this JVM", e);
        }
    }
}
