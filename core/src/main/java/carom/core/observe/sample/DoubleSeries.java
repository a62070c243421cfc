package carom.core.observe.sample;

import java.util.Arrays;

/** A growable list of doubles (one value per sample of a time series), without boxing. */
final class DoubleSeries {
    private double[] values;
    private int size;

    DoubleSeries() {
        values = new double[16];
    }

    DoubleSeries(double[] initial) {
        values = Arrays.copyOf(initial, Math.max(16, initial.length));
        size = initial.length;
    }

    void add(double v) {
        if (size == values.length) {
            values = Arrays.copyOf(values, 2 * size);
        }
        values[size++] = v;
    }

    double get(int i) {
        return values[i];
    }

    int size() {
        return size;
    }

    double[] toArray() {
        return Arrays.copyOf(values, size);
    }
}
