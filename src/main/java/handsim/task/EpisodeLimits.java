package handsim.task;

import handsim.config.Json;

/**
 * When an episode's object counts as caught or dropped.
 *
 * @param holdDistance the object is held if its centre is this close to the palm centre at the
 *     end of MIDDLE (m)
 * @param maxLoopSeconds a loop lasting longer is cut off (a time limit, not a drop)
 * @param maxDistance the object is lost if it gets this far from the shoulder (m)
 */
public record EpisodeLimits(double holdDistance, double maxLoopSeconds, double maxDistance) {

    public static EpisodeLimits parse(Json j) {
        j.allow("comment");
        EpisodeLimits l = new EpisodeLimits(j.positive("holdDistance"), j.positive("maxLoopSeconds"),
                j.positive("maxDistance"));
        j.requireNoUnknownFields();
        return l;
    }
}
