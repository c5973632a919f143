package handsim.cards.study;

import handsim.cards.tpe.Direction;
import handsim.report.Plot;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * The optimisation history of thesis Fig. 4.9 (Optuna's plot_optimization_history): each
 * complete trial's objective value as a dot, the best value so far as a line, against the trial
 * number. One plot, history.png, for one objective; history-NAME.png per objective for several.
 */
final class HistoryPlot {

    private HistoryPlot() {
    }

    static void write(Study study) throws IOException {
        StudyConfig c = study.config();
        for (int i = 0; i < c.objectives().size(); i++) {
            String name = c.objectives().get(i);
            Path png = study.dir().resolve(c.multiObjective() ? "history-" + name + ".png" : "history.png");
            plot(study.trials(), i, name, c.directions().get(i)).writePng(png);
        }
    }

    static Plot plot(List<TrialRecord> trials, int objective, String name, Direction direction) {
        List<TrialRecord> complete = trials.stream().filter(TrialRecord::isComplete).toList();
        double[] x = new double[complete.size()], y = new double[complete.size()], best = new double[complete.size()];
        for (int k = 0; k < x.length; k++) {
            TrialRecord t = complete.get(k);
            x[k] = t.number();
            y[k] = t.values()[objective];
            best[k] = k == 0 ? y[k] : direction == Direction.MAXIMIZE ? Math.max(best[k - 1], y[k]) : Math.min(best[k - 1], y[k]);
        }
        return new Plot("Optimization history: " + name + " (" + complete.size() + " complete trials)", "trial", name)
                .add("objective value", x, y, Plot.BLUE, Plot.Style.POINTS)
                .add("best value", x, best, Plot.RED, Plot.Style.LINE);
    }
}
