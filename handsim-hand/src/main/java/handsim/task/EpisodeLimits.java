package handsim.task;

import handsim.config.Json;

/**
 * When an episode's object counts as caught or dropped, and how runs of many episodes behave.
 *
 * @param holdDistance the object is held if its centre is this close to the palm centre at the
 *     end of MIDDLE (m)
 * @param maxLoopSeconds a loop lasting longer is cut off (a time limit, not a drop)
 * @param maxDistance the object is lost if it gets this far from the shoulder (m)
 * @param maxFailedThrowIns {@code demo} and the viewer, which throw a new object in whenever an
 *     episode ends, give up after this many episodes in a row whose throw-in was not caught
 * @param progressEveryLoops a long episode of {@code evaluate} prints a progress line with an
 *     estimate of the time left every this many loops
 */
public record EpisodeLimits(double holdDistance, double maxLoopSeconds, double maxDistance, int maxFailedThrowIns,
        int progressEveryLoops) {

    public static EpisodeLimits parse(Json j) {
        j.allow("comment");
        EpisodeLimits l = new EpisodeLimits(j.positive("holdDistance"), j.positive("maxLoopSeconds"),
                j.positive("maxDistance"), j.integer("maxFailedThrowIns", 1, 1000), j.integer("progressEveryLoops", 1, 1000000));
        j.requireNoUnknownFields();
        return l;
    }
}
