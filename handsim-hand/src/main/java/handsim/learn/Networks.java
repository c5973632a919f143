package handsim.learn;

import java.util.List;
import org.deeplearning4j.nn.conf.GradientNormalization;
import org.deeplearning4j.nn.conf.NeuralNetConfiguration;
import org.deeplearning4j.nn.conf.WorkspaceMode;
import org.deeplearning4j.nn.conf.distribution.UniformDistribution;
import org.deeplearning4j.nn.conf.layers.DenseLayer;
import org.deeplearning4j.nn.gradient.Gradient;
import org.deeplearning4j.nn.multilayer.MultiLayerNetwork;
import org.deeplearning4j.nn.weights.WeightInit;
import org.deeplearning4j.nn.workspace.LayerWorkspaceMgr;
import org.nd4j.linalg.activations.Activation;
import org.nd4j.linalg.api.buffer.DataType;
import org.nd4j.linalg.api.ndarray.INDArray;
import org.nd4j.linalg.factory.Nd4j;
import org.nd4j.linalg.learning.config.Adam;

/**
 * The deeplearning4j side of DDPG: building the MLPs and the three low-level moves the learner
 * needs (a training-mode forward pass, a gradient step from a given output gradient, a soft
 * target update).
 *
 * <p>Every layer is a {@code DenseLayer}, the last one included (no {@code OutputLayer}), so the
 * loss lives in {@link DdpgAgent}: it hands the output gradient to
 * {@link MultiLayerNetwork#backpropGradient}, which also returns the gradient with respect to
 * the input — the critic's dQ/da of the actor update (STACK.md). Networks use doubles and no
 * workspaces: the nets are tiny, and the plain-Java {@link Policy} must match them to 1e-6.
 */
final class Networks {

    private Networks() {
    }

    /**
     * An MLP: ReLU hidden layers (DL4J's default Xavier init), the last layer uniform in
     * [-finalInit, finalInit] (DDPG paper, sec. 7) with the given activation, Adam, optional L2
     * and per-layer gradient clipping. The seed fixes the weight initialisation.
     */
    static MultiLayerNetwork mlp(int in, List<Integer> hidden, int out, Activation outAct, double lr, double l2,
            LearnerConfig.Ddpg c, long seed) {
        NeuralNetConfiguration.Builder b = new NeuralNetConfiguration.Builder()
                .seed(seed)
                .dataType(DataType.DOUBLE)
                .trainingWorkspaceMode(WorkspaceMode.NONE)
                .inferenceWorkspaceMode(WorkspaceMode.NONE)
                .updater(new Adam(lr, c.adamBeta1(), c.adamBeta2(), c.adamEpsilon()))
                .weightInit(WeightInit.XAVIER);
        if (l2 > 0) {
            b.l2(l2);
        }
        if (c.gradientClip() > 0) {
            b.gradientNormalization(GradientNormalization.ClipL2PerLayer).gradientNormalizationThreshold(c.gradientClip());
        }
        NeuralNetConfiguration.ListBuilder list = b.list();
        int width = in;
        for (int h : hidden) {
            list.layer(new DenseLayer.Builder().nIn(width).nOut(h).activation(Activation.RELU).build());
            width = h;
        }
        list.layer(new DenseLayer.Builder().nIn(width).nOut(out).activation(outAct)
                .weightInit(new UniformDistribution(-c.finalLayerInit(), c.finalLayerInit())).build());
        MultiLayerNetwork net = new MultiLayerNetwork(list.build());
        net.init();
        return net;
    }

    /** A row-major double matrix as an nd4j array. */
    static INDArray matrix(double[] rowMajor, int rows, int cols) {
        return Nd4j.create(rowMajor, new long[] {rows, cols}, DataType.DOUBLE);
    }

    /** Forward pass in training mode, keeping each layer's input for a following backward pass. */
    static INDArray forwardForBackprop(MultiLayerNetwork net, INDArray input) {
        net.setInput(input);
        List<INDArray> activations = net.feedForward(true, false);
        return activations.get(activations.size() - 1);
    }

    /**
     * Backpropagates the output gradient of the last {@link #forwardForBackprop} call and returns
     * the gradient with respect to the input; the network's parameters are not changed.
     */
    static INDArray inputGradient(MultiLayerNetwork net, INDArray outputGradient) {
        return net.backpropGradient(outputGradient, LayerWorkspaceMgr.noWorkspaces()).getSecond();
    }

    /**
     * One Adam step from the output gradient of the last {@link #forwardForBackprop} call.
     * {@code outputGradient} holds per-example gradients dL_i/dy_i of a summed loss: DL4J's
     * updater divides by the batch size (minibatch mode), so the step follows the mean loss.
     */
    static void descend(MultiLayerNetwork net, INDArray outputGradient) {
        Gradient g = net.backpropGradient(outputGradient, LayerWorkspaceMgr.noWorkspaces()).getFirst();
        int iteration = net.getIterationCount();
        net.getUpdater().update(net, g, iteration, net.getEpochCount(), (int) outputGradient.size(0),
                LayerWorkspaceMgr.noWorkspaces());
        net.params().subi(g.gradient()); // the updater turned the gradient into the step, in place
        net.setIterationCount(iteration + 1); // Adam's bias correction counts steps
    }

    /** Soft target update (DDPG, Alg. 1): target = tau * net + (1 - tau) * target. */
    static void softUpdate(MultiLayerNetwork target, MultiLayerNetwork net, double tau) {
        target.params().muli(1 - tau).addi(net.params().mul(tau));
    }

    /** Plain copies of the rows of a matrix. */
    static double[] rowMajor(INDArray m) {
        return m.dup('c').data().asDouble();
    }
}
