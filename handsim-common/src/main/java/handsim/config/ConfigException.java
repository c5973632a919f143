package handsim.config;

/**
 * A model or configuration file is malformed or inconsistent. The message names the file, the
 * field (as a JSON path such as {@code bodies[3].joint.dofs[0].range}) and the bad value.
 */
public class ConfigException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public ConfigException(String message) {
        super(message);
    }

    public ConfigException(String message, Throwable cause) {
        super(message, cause);
    }
}
