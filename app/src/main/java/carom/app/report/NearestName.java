package carom.app.report;

import java.util.List;

/**
 * The known name a mistyped one most likely meant, for a "did you mean" in an error line: the same
 * name in other letter case, else the nearest by edit distance (insertions, deletions, substitutions
 * and swaps of neighbouring letters, ignoring case) if it is at most a third of the name's length
 * (at least 1); none otherwise, so that a name far from every known one gets no suggestion.
 */
final class NearestName {
    private NearestName() {
    }

    /** The suggestion for {@code given} among {@code known}, or null. */
    static String to(String given, List<String> known) {
        String lower = given.toLowerCase(java.util.Locale.ROOT);
        String best = null;
        int bestDistance = Math.max(1, given.length() / 3) + 1;
        for (String name : known) {
            String candidate = name.toLowerCase(java.util.Locale.ROOT);
            if (candidate.equals(lower)) {
                return name;
            }
            int d = distance(lower, candidate);
            if (d < bestDistance) {
                bestDistance = d;
                best = name;
            }
        }
        return best;
    }

    /** Optimal string alignment distance: Levenshtein's with swaps of neighbours. */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
