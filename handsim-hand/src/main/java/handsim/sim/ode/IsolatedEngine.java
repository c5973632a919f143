package handsim.sim.ode;

import handsim.model.HandModel;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import org.ode4j.ode.OdeHelper;

/**
 * Simulators for stepping several worlds on several threads of one JVM: for ode4j's quickStep,
 * each with an ode4j of its own class loader.
 *
 * <p>Why: ode4j keeps process-wide mutable state. quickStep shuffles its constraint rows with
 * ODE's one random generator ({@code Misc.dRandInt}, reseeded by {@link OdeSimulator#reset}), so
 * two worlds stepped on two threads draw from each other's sequence and their results depend on
 * thread timing; {@code DxQuickStep.INSTANCE} and its (opt-in) reused buffers are shared too.
 * Loading ode4j and this package again in a private, child-first class loader gives each such
 * simulator its own copy of every static: a world is then a function of its own seed alone, with
 * the solver unchanged (the alternative, switching the random reordering off, changes the
 * physics and still leaves the other statics shared). The cost is one more copy of ode4j's
 * classes (a few MB of metaspace) and its own JIT warm-up.
 *
 * <p>One simulator per loader: a loader's simulator must be stepped by one thread at a time,
 * which {@link Simulator} asks of every simulator anyway.
 *
 * <p>handsim's own step ({@link SimConfig.Stepper#HANDSIM}) draws its row order from a generator
 * of its own world and leaves quickStep's statics untouched; what else of ode4j a step runs (the
 * colliders, bodies, geoms) keeps no state across worlds. Its simulators share the one ode4j of
 * the application's class loader, bit-identical to separate runs whatever the number of threads
 * ({@code HandsimWorkersTest}).
 */
public final class IsolatedEngine {

    private static final String OWN_PACKAGE = OdeSimulator.class.getPackageName() + ".";
    private static final String ODE4J = "org.ode4j.";

    private IsolatedEngine() {
    }

    /**
     * A new {@link OdeSimulator} that steps independently of every other: on a private copy of
     * ode4j when ode4j's quickStep steps it, on the shared one when handsim's step does.
     */
    public static Simulator simulator(HandModel model, SimConfig config) {
        if (config.stepper() == SimConfig.Stepper.HANDSIM) {
            return new OdeSimulator(model, config);
        }
        URL[] path = {location(OdeSimulator.class), location(OdeHelper.class)};
        ChildFirstLoader loader = new ChildFirstLoader(path, OdeSimulator.class.getClassLoader());
        try {
            Class<?> type = loader.loadClass(OdeSimulator.class.getName());
            return (Simulator) type.getConstructor(HandModel.class, SimConfig.class).newInstance(model, config);
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            throw new IllegalStateException("cannot create an isolated ode4j simulator", e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot create an isolated ode4j simulator", e);
        }
    }

    private static URL location(Class<?> type) {
        var source = type.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            throw new IllegalStateException("cannot find where " + type.getName() + " was loaded from");
        }
        return source.getLocation();
    }

    /** Defines ode4j and this package itself; everything else (the model, math, the Simulator interface) comes from the parent. */
    private static final class ChildFirstLoader extends URLClassLoader {

        static {
            registerAsParallelCapable();
        }

        ChildFirstLoader(URL[] path, ClassLoader parent) {
            super("handsim-ode4j", path, parent);
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (!name.startsWith(ODE4J) && !name.startsWith(OWN_PACKAGE)) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> c = findLoadedClass(name);
                if (c == null) {
                    c = findClass(name);
                }
                if (resolve) {
                    resolveClass(c);
                }
                return c;
            }
        }
    }
}
