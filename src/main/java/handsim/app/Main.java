package handsim.app;

import handsim.config.ConfigException;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code handsim}: the launcher's entry point; every subcommand lives in its own class. */
@Command(name = "handsim", mixinStandardHelpOptions = true, version = "handsim 0.1.0",
        description = "A physically simulated arm and hand that catches and throws (Luo et al., MIG 2021).",
        subcommands = {DemoCommand.class, InfoCommand.class, BenchCommand.class, EvaluateCommand.class, RenderCommand.class, ExportCommand.class, ViewCommand.class, TrainCommand.class, DaggerCommand.class, WarmstartCommand.class, CurvesCommand.class})
public final class Main implements Runnable {

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** Runs a command line and returns the exit code (0 ok, 2 bad input, 1 failure). */
    public static int run(String... args) {
        CommandLine cli = new CommandLine(new Main());
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            if (ex instanceof ConfigException || ex instanceof IllegalArgumentException) {
                commandLine.getErr().println("handsim " + commandLine.getCommandName() + ": " + ex.getMessage());
                return 2;
            }
            throw ex;
        });
        cli.setParameterExceptionHandler((ex, params) -> {
            CommandLine c = ex.getCommandLine();
            c.getErr().println("handsim " + c.getCommandName() + ": " + ex.getMessage() + " (see --help)");
            return 2;
        });
        return cli.execute(args);
    }

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }
}
