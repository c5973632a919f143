package handsim.app;

import handsim.cards.contact.BudgetExceeded;
import handsim.config.ConfigException;
import handsim.report.Locks;
import handsim.report.Stop;
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
        Locks.describeProcess("scripts/handsim " + String.join(" ", args));
        Signals.install();
        System.exit(run(args));
    }

    /**
     * Runs a command line and returns the exit code: 0 ok; 2 bad input (an option, a config, a
     * model, a run folder), said in one line; 1 a failure of the run itself (a diverged
     * simulation, a file that cannot be written, a card trial past its budget), said in one line;
     * 128 + the signal's number for a run stopped cleanly by SIGTERM (143), SIGINT (130) or SIGHUP
     * (129), said in one line. Anything else is a bug and shows its stack trace.
     */
    public static int run(String... args) {
        Stop.reset();
        StopRecords.clear();
        try {
            OutputPaths.holdEarly(args); // a folder another process works in: refused before anything is loaded
        } catch (Locks.Held held) {
            OutputPaths.end(true);
            String command = "";
            for (int i = 0; i < args.length && !args[i].startsWith("-"); i++) {
                command = args[i]; // the subcommand's name, as picocli's messages give it
            }
            System.err.println("handsim " + command + ": " + held.getMessage());
            return 2;
        }
        CommandLine cli = new CommandLine(new Main());
        cli.setExecutionStrategy(parsed -> {
            OutputPaths.begin(parsed);
            return new CommandLine.RunLast().execute(parsed);
        });
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            String failure = ex instanceof ConfigException || ex instanceof IllegalArgumentException ? ex.getMessage()
                    : ex instanceof SimulationDiverged ? "the simulation diverged: " + ex.getMessage()
                    : ex instanceof RunFailed || ex instanceof Stop.Stopped || ex instanceof RemoteFailure ? ex.getMessage()
                    : ex instanceof BudgetExceeded ? "the trial went past its budget: " + ex.getMessage()
                    : ex instanceof IOException io ? fileProblem(io)
                    : ex instanceof UncheckedIOException io ? fileProblem(io.getCause()) : null;
            if (failure == null) {
                throw ex;
            }
            if (ex instanceof Stop.Stopped stopped) {
                StopRecords.write(stopped.signal());
            }
            commandLine.getErr().println("handsim " + commandLine.getCommandName() + ": " + failure.lines().findFirst().orElse(""));
            return ex instanceof Stop.Stopped s ? s.status() : ex instanceof ConfigException || ex instanceof IllegalArgumentException ? 2 : 1;
        });
        cli.setParameterExceptionHandler((ex, params) -> {
            CommandLine c = ex.getCommandLine();
            String who = c.getParent() == null ? "handsim" : "handsim " + c.getCommandName();
            c.getErr().println(who + ": " + ex.getMessage().lines().findFirst().orElse("") + " (see --help)");
            return 2;
        });
        int status = 1;
        try {
            status = cli.execute(args);
            return status;
        } finally {
            OutputPaths.end(status != 0);
        }
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
