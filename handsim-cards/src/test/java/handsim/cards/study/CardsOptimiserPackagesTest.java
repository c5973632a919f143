package handsim.cards.study;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The optimiser's packages import what their package-info says: the sampler the JDK and
 * commons-math3 only; the study runner also Jackson, handsim.config, handsim.report and
 * handsim.rollout (the portable calls its trials travel as to a cluster, no cluster library).
 * Neither imports a physics, learning, viewer, command-line or cluster library.
 */
@Tag("fast")
class CardsOptimiserPackagesTest {

    private static final Pattern IMPORT = Pattern.compile("^import (?:static )?([\\w.]+)", Pattern.MULTILINE);

    @Test
    void theSamplerImportsTheJdkAndCommonsMathOnly() throws IOException {
        assertEquals(List.of(), offenders("handsim/cards/tpe", "java.", "org.apache.commons.math3.", "handsim.cards.tpe."));
    }

    @Test
    void theStudyRunnerImportsTheSamplerConfigReportAndRolloutOnly() throws IOException {
        assertEquals(List.of(), offenders("handsim/cards/study", "java.", "com.fasterxml.jackson.", "handsim.config.", "handsim.report.",
                "handsim.rollout.", "handsim.cards.tpe.", "handsim.cards.study."));
    }

    private static List<String> offenders(String pkg, String... allowed) throws IOException {
        List<String> out = new ArrayList<>();
        try (Stream<Path> files = Files.list(Path.of("handsim-cards/src/main/java").resolve(pkg))) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Matcher m = IMPORT.matcher(Files.readString(f));
                while (m.find()) {
                    String imported = m.group(1);
                    if (Stream.of(allowed).noneMatch(imported::startsWith)) {
                        out.add(f.getFileName() + ": " + imported);
                    }
                }
            }
        }
        return out;
    }
}
