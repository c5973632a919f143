package handsim.app;

import handsim.config.ConfigException;
import handsim.rollout.RemoteFailure;
import handsim.sim.SimulationDiverged;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileSystemException;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code handsim}: the launcher's entry point; every subcommand lives in its own class. */
@Command(name = "handsim", mixinStandardHelpOptions = true, version = "handsim 0.1.0",
        description = "A physically simulated arm and hand that catches and throws (Luo et al., MIG 2021).",
        subcommands = {DemoCommand.class, InfoCommand.class, BenchCommand.class, EvaluateCommand.class, RenderCommand.class,
                ExportCommand.class, ViewCommand.class, TrainCommand.class, DaggerCommand.class, WarmstartCommand.class,
                CurvesCommand.class, CompareCommand.class, CardsCommand.class})
public final class Main implements Runnable {

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /**
     * Runs a command line and returns the exit code: 0 ok; 2 bad input (an option, a config, a
     * model, a run folder), said in one line; 1 a failure of the run itself (a diverged
     * simulation, a file that cannot be written), said in one line. Anything else is a bug and
     * shows its stack trace.
     */
    public static int run(String... args) {
        CommandLine cli = new CommandLine(new Main());
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            String failure = ex instanceof ConfigException || ex instanceof IllegalArgumentException ? ex.getMessage()
                    : ex instanceof SimulationDiverged ? "the simulation diverged: " + ex.getMessage()
                    : ex instanceof RunFailed || ex instanceof RemoteFailure ? ex.getMessage()
                    : ex instanceof IOException io ? fileProblem(io)
                    : ex instanceof UncheckedIOException io ? fileProblem(io.getCause()) : null;
            if (failure == null) {
                throw ex;
            }
            commandLine.getErr().println("handsim " + commandLine.getCommandName() + ": " + failure.lines().findFirst().orElse(""));
            return ex instanceof ConfigException || ex instanceof IllegalArgumentException ? 2 : 1;
        });
        cli.setParameterExceptionHandler((ex, params) -> {
            CommandLine c = ex.getCommandLine();
            String who = c.getParent() == null ? "handsim" : "handsim " + c.getCommandName();
            c.getErr().println(who + ": " + ex.getMessage().lines().findFirst().orElse("") + " (see --help)");
            return 2;
        });
        return cli.execute(args);
    }

    /** A failed file operation in a few words (Java's messages are often just the path). */
    private static String fileProblem(IOException e) {
        return e instanceof FileSystemException f && f.getFile() != null ? f.getFile() + ": " + OutputPaths.reason(e)
                : OutputPaths.reason(e);
    }

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }
}
