package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.evaluation.EpisodeJournal;
import handsim.evaluation.EvaluationSetup;
import java.nio.file.Path;
import java.util.List;

/**
 * The journal of {@code evaluate --json FILE}: the run's finished episodes, kept in
 * FILE.episodes.jsonl while the run goes, which the same command, killed and run again, goes on from.
 */
final class EvaluationJournals {

    private EvaluationJournals() {
    }

    /** Where --json's finished episodes are kept while the run goes: FILE.episodes.jsonl. */
    static Path file(Path json) {
        return json.resolveSibling(json.getFileName() + ".episodes.jsonl");
    }

    /**
     * The journal of --json {@code json}: the run's episodes already finished by the same command,
     * killed. What makes the episodes what they are signs it: the spec {@code record}, but for the
     * episode and test counts (more episodes of the same run keep the first ones).
     */
    static EpisodeJournal open(Path json, ObjectNode record, String commit, List<String> args) {
        ObjectNode signature = record.deepCopy();
        signature.remove(List.of("episodes", "tests"));
        EpisodeJournal journal = EpisodeJournal.open(file(json), signature, commit);
        StopRecords.evaluation(json, journal, args, commit);
        if (journal.finished() > 0) {
            System.out.printf("resuming: %d finished episodes read from %s%s%n", journal.finished(), journal.file(),
                    journal.droppedLines() > 0 ? " (" + journal.droppedLines() + " line cut short by a kill dropped)" : "");
        }
        return journal;
    }

    /** {@code s} with its finished episodes written to, and read from, {@code journal}. */
    static EvaluationSetup with(EvaluationSetup s, EpisodeJournal journal) {
        return new EvaluationSetup(s.controller(), s.object(), s.limits(), s.launches(), s.config(), s.policies(), s.planning(),
                s.twins(), s.watcher(), journal, s.console());
    }
}
