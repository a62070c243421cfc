package carom.core.scene;

import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * What the Jazzer fuzz tests of scene input share (core's {@code SceneReaderFuzzTest}, the app's
 * {@code SimulateFuzzTest}): the scene format's dictionary ({@link #DICTIONARY}, for
 * {@code @DictionaryFile}) and a per-input deadline.
 */
public final class FuzzInputs {
    /** The libFuzzer dictionary of the scene format's words, a test resource of core. */
    public static final String DICTIONARY = "/carom/core/scene/scene-format.dict";

    private FuzzInputs() {
    }

    /**
     * Runs {@code work} on a thread of its own and returns its answer, rethrowing what it threw; fails
     * if there is no answer within {@code seconds}. Per input rather than JUnit's @Timeout, which in
     * fuzzing mode would bound the whole fuzzing session.
     */
    public static <T> T answerWithinDeadline(long seconds, Callable<T> work) throws Throwable {
        FutureTask<T> task = new FutureTask<>(work);
        Thread.ofPlatform().daemon().name("fuzz-input").start(task);
        try {
            return task.get(seconds, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            task.cancel(true);
            throw new AssertionError("no answer within " + seconds + " s: the input hangs");
        } catch (ExecutionException e) {
            throw e.getCause();
        }
    }
}
