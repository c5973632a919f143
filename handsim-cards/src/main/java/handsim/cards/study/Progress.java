package handsim.cards.study;

import handsim.report.Durations;
import java.io.PrintStream;
import java.util.List;
import java.util.Locale;

/** A study's progress lines: one when it starts, one per finished trial with the best so far and an ETA, one at the end. */
final class Progress {

    private final PrintStream out;
    private final Study study;
    private final int nTrials;
    private final long t0 = System.nanoTime();
    private int finishedThisRun;

    Progress(PrintStream out, Study study, int nTrials) {
        this.out = out;
        this.study = study;
        this.nTrials = nTrials;
    }

    /** The first line; {@code where} says what runs the trials ("2 workers"). */
    void start(String where) {
        StudyConfig c = study.config();
        print(String.format(Locale.ROOT, "study %s: %d trials, %d finished, seed %d; %s, at most %d trials at once; %s, %d start-up trials",
                study.dir(), nTrials, finishedInRange(), study.seed(), where, c.parallelTrials(),
                c.multiObjective() ? "MOTPE" : "TPE", c.sampler().nStartupTrials()));
    }

    void finished(TrialRecord t, int running) {
        finishedThisRun++;
        double elapsed = (System.nanoTime() - t0) * 1e-9;
        int done = finishedInRange();
        double eta = (nTrials - done) * elapsed / finishedThisRun;
        print(String.format(Locale.ROOT, "trial %d %s in %.3g s: %s | %s | %d/%d finished, %d running | elapsed %s, ETA %s",
                t.number(), t.isComplete() ? "complete" : "failed", t.seconds(), t.isComplete() ? values(t) : t.error(), best(),
                done, nTrials, running, Durations.clock(elapsed), Durations.clock(eta)));
    }

    void end() {
        print(String.format(Locale.ROOT, "study %s: %d/%d trials finished in %s; %s", study.dir(), finishedInRange(), nTrials,
                Durations.clock((System.nanoTime() - t0) * 1e-9), best()));
    }

    private String values(TrialRecord t) {
        List<String> names = study.config().objectives();
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < names.size(); i++) {
            s.append(i == 0 ? "" : ", ").append(names.get(i)).append(' ').append(number(t.values()[i]));
        }
        return s.toString();
    }

    private String best() {
        if (study.config().multiObjective()) {
            return "Pareto front of " + study.paretoFront().size() + " trials";
        }
        return study.best().map(b -> "best " + number(b.values()[0]) + " (trial " + b.number() + ")").orElse("no complete trial yet");
    }

    private int finishedInRange() {
        return (int) study.trials().stream().filter(t -> t.number() < nTrials).count();
    }

    private void print(String line) {
        if (out != null) {
            out.println(line);
            out.flush();
        }
    }

    private static String number(double v) {
        return String.format(Locale.ROOT, "%.4g", v);
    }
}
