package carom.app;

import java.util.ListResourceBundle;

/**
 * {@code resume}'s wording of the options it shares with {@code simulate} (picocli reads an option's
 * {@code descriptionKey} here before its own description): a continued run takes its end time, sampling
 * and observables from the checkpoint, so these options say so. Public only because
 * {@link java.util.ResourceBundle} instantiates it.
 */
public final class ResumeHelp extends ListResourceBundle {
    @Override
    protected Object[][] getContents() {
        return new Object[][] {
                {"until", "Simulated end time, overriding the run's; not before the checkpoint's time."},
                {"report", "Folder (new or empty) for the observables the run had (--observe), accumulated over the whole run."},
                {"trajectory", "Write the samples from the checkpoint on as frames (extended XYZ, or GSD for a name ending in .gsd); the run must have had --every."},
                {"checkpoint", "Write checkpoints of the continued run here."},
                {"checkpoint-every", "Simulated time between checkpoints; default: the checkpoint's interval."},
        };
    }
}
