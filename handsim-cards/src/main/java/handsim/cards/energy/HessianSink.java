package handsim.cards.energy;

/** Receives element Hessians: {@code h} is row-major 3k x 3k over the element's k nodes. */
public interface HessianSink {

    void add(int[] nodes, int k, double[] h);
}
