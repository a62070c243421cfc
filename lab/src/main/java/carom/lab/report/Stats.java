package carom.lab.report;

/**
 * Mean and sample standard deviation of a few trials: the lab's one statistics class. The standard
 * deviation divides by n - 1, as the thesis's tables do (Table 4.1's 16-disc row, trials 141, 143,
 * 141, 141, 142, has 0.894), and is summed in two passes, over deviations from the mean: the one-pass
 * sum of squares loses every digit of a small spread between large values.
 *
 * @param count how many values
 * @param mean  their mean, NaN for none
 * @param sd    their sample standard deviation, NaN for fewer than two
 */
public record Stats(int count, double mean, double sd) {
    public static Stats of(double... values) {
        int n = values.length;
        if (n == 0) {
            return new Stats(0, Double.NaN, Double.NaN);
        }
        double sum = 0;
        for (double v : values) {
            sum += v;
        }
        double mean = sum / n;
        if (n == 1) {
            return new Stats(1, mean, Double.NaN);
        }
        // Two passes: the squares of deviations, not of values, so large equal values lose no digits.
        double squares = 0;
        for (double v : values) {
            squares += (v - mean) * (v - mean);
        }
        return new Stats(n, mean, Math.sqrt(squares / (n - 1)));
    }

    public static Stats of(java.util.Collection<Double> values) {
        return of(values.stream().mapToDouble(Double::doubleValue).toArray());
    }
}
