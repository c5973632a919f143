package handsim.report;

import java.nio.file.Path;

/** A process that holds a folder ({@link Locks}) until it is killed: the other process of {@link LocksTest}. */
public final class LockHolder {

    private LockHolder() {
    }

    public static void main(String[] args) throws InterruptedException {
        Locks.describeProcess("LockHolder " + args[0]);
        Locks.holdFolder(Path.of(args[0]), "the folder " + args[0], System.out::println);
        System.out.println("held");
        Thread.sleep(120_000);
    }
}
