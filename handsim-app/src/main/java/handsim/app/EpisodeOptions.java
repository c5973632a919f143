package handsim.app;

import picocli.CommandLine.Option;

/**
 * Which episodes a run plays, declared once for every command that throws an object: the object
 * and the seed of the first episode (episode i has seed {@code --seed} + i).
 */
final class EpisodeOptions {

    @Option(names = "--object", defaultValue = "sphere",
            description = "the object thrown: sphere, can, cuboid or club (configs/objects; default: ${DEFAULT-VALUE})")
    String object;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the first episode (default: ${DEFAULT-VALUE})")
    long seed;
}
