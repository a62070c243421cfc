package carom.lab.study;

/**
 * One line of the study: an engine and setting on a scene, what it measured, and the reference it is
 * judged against (the serial engine's pressure and its positions at the short horizon).
 *
 * @param dt        the absolute step of a stepping engine, else NaN
 * @param skipped   why the setting was not run (dyn4j on a periodic box), or null
 * @param measured  null when skipped
 * @param zExact    the exact reference's reduced pressure, NaN without one
 * @param zExactError its error bar
 * @param deviation distance from the reference's positions at the short horizon, null without a reference
 */
record Row(StudyScene scene, Setting setting, double dt, double until, double shortUntil, String skipped,
           Measured measured, double zExact, double zExactError, StateErrors.Deviation deviation) {
    boolean ran() {
        return skipped == null;
    }

    /** |Z − Z_exact|, NaN where either is missing. */
    double pressureError() {
        return ran() ? Math.abs(measured.z() - zExact) : Double.NaN;
    }

    double deviationRms() {
        return deviation == null ? Double.NaN : deviation.rms();
    }

    double deviationMax() {
        return deviation == null ? Double.NaN : deviation.max();
    }
}
