package handsim.cards.study;

import handsim.report.Plot;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The Pareto front of a study of several objectives (thesis Fig. 4.11) as pairwise projections,
 * pareto.png: every complete trial a grey dot, the Pareto trials red, the chosen trial green,
 * each axis an objective in the units its config names (scaled by {@code unit}).
 */
final class ParetoPlot {

    private ParetoPlot() {
    }

    /**
     * Writes pareto.png into the study's folder, the objectives' values multiplied by {@code
     * scale} and labelled with {@code unit} (say 1000 and "mm").
     */
    static void write(Study study, double scale, String unit) throws IOException {
        StudyConfig c = study.config();
        List<TrialRecord> complete = study.trials().stream().filter(TrialRecord::isComplete).toList();
        List<TrialRecord> front = study.paretoFront();
        Optional<TrialRecord> chosen = study.chosen();
        List<Plot> panels = new ArrayList<>();
        int n = c.objectives().size();
        for (int a = 0; a < n; a++) {
            for (int b = a + 1; b < n; b++) {
                int i = a;
                int j = b;
                String xName = c.objectives().get(i) + (unit.isEmpty() ? "" : " (" + unit + ")");
                String yName = c.objectives().get(j) + (unit.isEmpty() ? "" : " (" + unit + ")");
                Plot p = new Plot("Pareto front, " + complete.size() + " trials: " + c.objectives().get(i) + " vs " + c.objectives().get(j),
                        xName, yName);
                p.add("trial", column(complete, i, scale), column(complete, j, scale), Plot.GREY, Plot.Style.POINTS);
                p.add("Pareto trial (" + front.size() + ")", column(front, i, scale), column(front, j, scale), Plot.RED, Plot.Style.POINTS);
                chosen.ifPresent(t -> p.add("chosen: trial " + t.number(), column(List.of(t), i, scale), column(List.of(t), j, scale),
                        Plot.GREEN, Plot.Style.POINTS));
                panels.add(p);
            }
        }
        Plot.writePngRow(study.dir().resolve("pareto.png"), panels);
    }

    private static double[] column(List<TrialRecord> trials, int objective, double scale) {
        return trials.stream().mapToDouble(t -> scale * t.values()[objective]).toArray();
    }
}
