package handsim.learn;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;

/**
 * The DDPG replay memory: a ring of transitions (s, a, r, s', terminal) in primitive arrays.
 * Observations are kept raw; they are normalised when a batch is drawn, with the statistics of
 * that moment. {@code terminal} marks a real episode end (no bootstrap); a truncated last step
 * is stored as not terminal, so the TD target bootstraps from s'.
 */
public final class ReplayBuffer {

    /** A batch of transitions, row-major. */
    public record Batch(int size, double[] obs, double[] actions, double[] rewards, double[] nextObs,
            boolean[] terminal) {
    }

    private final int capacity;
    private final int obsSize;
    private final int actionSize;
    private final double[] obs;
    private final double[] actions;
    private final double[] rewards;
    private final double[] nextObs;
    private final boolean[] terminal;
    private int next;
    private int size;

    public ReplayBuffer(int capacity, int obsSize, int actionSize) {
        this.capacity = capacity;
        this.obsSize = obsSize;
        this.actionSize = actionSize;
        obs = new double[capacity * obsSize];
        actions = new double[capacity * actionSize];
        rewards = new double[capacity];
        nextObs = new double[capacity * obsSize];
        terminal = new boolean[capacity];
    }

    public int size() {
        return size;
    }

    public int capacity() {
        return capacity;
    }

    public void add(double[] s, double[] a, double r, double[] s2, boolean isTerminal) {
        if (s.length != obsSize || s2.length != obsSize || a.length != actionSize) {
            throw new IllegalArgumentException("transition sizes " + s.length + "/" + a.length + "/" + s2.length
                    + ", expected " + obsSize + "/" + actionSize + "/" + obsSize);
        }
        System.arraycopy(s, 0, obs, next * obsSize, obsSize);
        System.arraycopy(a, 0, actions, next * actionSize, actionSize);
        rewards[next] = r;
        System.arraycopy(s2, 0, nextObs, next * obsSize, obsSize);
        terminal[next] = isTerminal;
        next = (next + 1) % capacity;
        size = Math.min(size + 1, capacity);
    }

    /** {@code n} transitions drawn uniformly with replacement. */
    public Batch sample(int n, Rng rng) {
        if (size == 0) {
            throw new IllegalStateException("cannot sample from an empty replay buffer");
        }
        Batch b = new Batch(n, new double[n * obsSize], new double[n * actionSize], new double[n], new double[n * obsSize],
                new boolean[n]);
        for (int k = 0; k < n; k++) {
            int i = rng.nextInt(size);
            System.arraycopy(obs, i * obsSize, b.obs(), k * obsSize, obsSize);
            System.arraycopy(actions, i * actionSize, b.actions(), k * actionSize, actionSize);
            b.rewards()[k] = rewards[i];
            System.arraycopy(nextObs, i * obsSize, b.nextObs(), k * obsSize, obsSize);
            b.terminal()[k] = terminal[i];
        }
        return b;
    }

    // ---- checkpoint state -----------------------------------------------------------------

    void write(DataOutputStream out) throws IOException {
        out.writeInt(capacity);
        out.writeInt(obsSize);
        out.writeInt(actionSize);
        out.writeInt(next);
        out.writeInt(size);
        for (int i = 0; i < size; i++) {
            for (int j = 0; j < obsSize; j++) {
                out.writeDouble(obs[i * obsSize + j]);
                out.writeDouble(nextObs[i * obsSize + j]);
            }
            for (int j = 0; j < actionSize; j++) {
                out.writeDouble(actions[i * actionSize + j]);
            }
            out.writeDouble(rewards[i]);
            out.writeBoolean(terminal[i]);
        }
    }

    static ReplayBuffer read(DataInputStream in) throws IOException {
        ReplayBuffer b = new ReplayBuffer(in.readInt(), in.readInt(), in.readInt());
        b.next = in.readInt();
        b.size = in.readInt();
        for (int i = 0; i < b.size; i++) {
            for (int j = 0; j < b.obsSize; j++) {
                b.obs[i * b.obsSize + j] = in.readDouble();
                b.nextObs[i * b.obsSize + j] = in.readDouble();
            }
            for (int j = 0; j < b.actionSize; j++) {
                b.actions[i * b.actionSize + j] = in.readDouble();
            }
            b.rewards[i] = in.readDouble();
            b.terminal[i] = in.readBoolean();
        }
        return b;
    }
}
