package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.evaluation.EpisodeJournal;
import handsim.report.Outputs;
import handsim.report.Stop;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * What a command writes when a stop request ({@link Stop}: SIGTERM, Ctrl-C) ends it early, for
 * the commands whose loops live in shared code: a command registers it once ({@link #onStop}),
 * and {@link Main#run} writes it when the command ends {@link Stop.Stopped stopped}.
 */
final class StopRecords {

    /** A record to write. */
    @FunctionalInterface
    interface Record {
        void write(String signal) throws IOException;
    }

    private static final List<Record> RECORDS = new ArrayList<>();

    private StopRecords() {
    }

    /** Forgets the records of an earlier command run in this process. */
    static synchronized void clear() {
        RECORDS.clear();
    }

    static synchronized void onStop(Record record) {
        RECORDS.add(record);
    }

    /** Writes the records for a run that {@code signal} stopped; a record that fails is said on standard error. */
    static synchronized void write(String signal) {
        for (Record r : RECORDS) {
            try {
                r.write(signal);
            } catch (IOException | RuntimeException e) {
                System.err.println("handsim: could not record the interruption: " + e.getMessage());
            }
        }
        RECORDS.clear();
    }

    /**
     * {@code evaluate --json F} stopped: F says the run was interrupted, how many episodes it
     * finished and where they are kept (the journal, from which the same command goes on), with
     * the command line and commit.
     */
    static void evaluation(Path json, EpisodeJournal journal, List<String> args, String commit) {
        onStop(signal -> {
            ObjectNode o = JsonNodeFactory.instance.objectNode();
            o.put("interrupted", signal);
            o.put("episodes_finished", journal.finished());
            o.put("journal", journal.file().toString());
            o.put("resume", "run the same command again: it reads the finished episodes back from the journal and runs the rest");
            o.set("provenance", Provenance.of(args, commit));
            Outputs.writeJson(json, o);
        });
    }
}
