/**
 * Learning, with no physics: the {@link handsim.learn.Env} interface a task implements (one
 * decision per step, terminal vs truncated ends), DDPG on deeplearning4j (Lillicrap et al. 2015,
 * the learner of paper sec. 3.7), its replay buffer, exploration noise and observation
 * normaliser, whole-agent checkpoints, the training driver and its metrics, the plain-Java
 * {@link handsim.learn.Policy} that is shipped and evaluated, CMA-ES (Hansen 2006) and actor
 * pretraining by regression for the imitation warm start of sec. 4.4.
 *
 * <p>Actions are always in [-1, 1]^k (the actor's tanh range); each task maps them onto its
 * own parameter box (see {@link handsim.control.ThrowSpace}). This package imports neither
 * ode4j nor LWJGL; it sees a task only through {@link handsim.learn.Env}.
 */
package handsim.learn;
