package carom.lab.experiment;

import carom.lab.report.Stats;
import java.util.List;
import java.util.Map;

/**
 * The thesis's published results (Schrock 2016, "Multithreaded Collision Detection with Akka's Actor
 * Library in Scala", chapter 4), transcribed from its text: every trial as printed, so that the mean
 * and standard deviation can be recomputed and the transcription checked against the printed ones.
 * The tables name no unit; their size (7.8 thousand for 100,000 discs on one thread) says milliseconds.
 */
final class ThesisNumbers {
    /**
     * One row of a thesis table.
     *
     * @param discs          particles ("NumParticles"; Table 4.4 prints hundreds of thousands)
     * @param trialsMs       each trial's time as printed
     * @param printedMeanMs  the average column as printed
     * @param printedSdMs    the standard deviation column as printed, NaN where the table has none
     */
    record Row(int discs, double[] trialsMs, double printedMeanMs, double printedSdMs) {
        Stats stats() {
            return Stats.of(trialsMs);
        }
    }

    /** The machine of every thesis run (chapter 4's first paragraph). */
    static final String MACHINE = "\"pandora02\", 32 cores at 2.1 GHz (thesis, start of chapter 4)";
    /** Section 4.4: about 13 million messages for 55,000 collisions with 200,000 particles. */
    static final int MESSAGES_DISCS = 200_000;
    static final double MESSAGES_PER_COLLISION = 237.8;
    static final double MESSAGES_PER_PARTICLE = 65.7;
    static final int COLLISIONS_AT_200K = 55_000;
    /** Chapter 5: "At 3 million particles there are close to 1800 actors running simultaneously". */
    static final int ACTORS_AT_3M = 1800;
    static final int ACTORS_AT_3M_DISCS = 3_000_000;

    /**
     * Table 4.1 prints 1.416 as the 16-disc average, whose trials (141 to 143) average 141.6: a
     * misprint. Everywhere else the printed averages are the trials' means.
     */
    static final String MISPRINT = "Table 4.1 prints the 16-disc average as 1.416; its trials (141 to 143) average 141.6, "
            + "which is shown here";

    private ThesisNumbers() {
    }

    /** Tables 4.1 (single thread), 4.2 (multithread, non actor) and 4.3 (actor): 5 trials, 16 to 1M discs. */
    static List<Row> table(EngineRole role) {
        return switch (role) {
            case SINGLE_THREAD -> SINGLE;
            case NON_ACTOR -> NON_ACTOR;
            case ACTOR -> ACTOR;
        };
    }

    /**
     * Table 4.4, the large runs of the two parallel models: 2 trials each, 0 to 3M discs in steps of
     * 200,000 (the table counts hundreds of thousands; its first row is printed as 0). It prints no
     * standard deviation.
     */
    static List<Row> largeTable(EngineRole role) {
        return LARGE.getOrDefault(role, List.of());
    }

    private static Row row(int discs, double[] trials, double mean, double sd) {
        return new Row(discs, trials, mean, sd);
    }

    private static final List<Row> SINGLE = List.of(
            row(16, new double[] {141, 143, 141, 141, 142}, 1.416, 0.894427191),
            row(100000, new double[] {7850, 7865, 7848, 7751, 7871}, 7837, 49.05609035),
            row(200000, new double[] {14633, 14493, 14481, 14436, 14516}, 14511.8, 73.74754233),
            row(300000, new double[] {21194, 21047, 20996, 21839, 20866}, 21188.4, 382.1862112),
            row(400000, new double[] {29690, 29761, 29327, 29734, 28269}, 29356.2, 632.6284059),
            row(500000, new double[] {36468, 36928, 38328, 35431, 36857}, 36802.4, 1041.486102),
            row(600000, new double[] {45395, 44071, 45230, 43214, 43473}, 44276.6, 997.1149884),
            row(700000, new double[] {52793, 54073, 54807, 53313, 50945}, 53186.2, 1466.890316),
            row(800000, new double[] {64189, 60667, 58876, 59014, 64599}, 61469, 2765.374206),
            row(900000, new double[] {71741, 92576, 68030, 73725, 69694}, 75153.2, 9972.207213),
            row(1000000, new double[] {79973, 83412, 75258, 82729, 76925}, 79659.4, 3551.480719));

    private static final List<Row> NON_ACTOR = List.of(
            row(16, new double[] {4240, 92, 102, 132, 135}, 940.2, 1844.738247),
            row(100000, new double[] {2671, 2714, 2645, 2555, 2713}, 2659.6, 65.37430688),
            row(200000, new double[] {5071, 5206, 5600, 4869, 5923}, 5333.8, 424.1034072),
            row(300000, new double[] {6412, 5828, 5588, 5950, 6205}, 5996.6, 321.5350681),
            row(400000, new double[] {9071, 7870, 7798, 7712, 7640}, 8018.2, 594.9018406),
            row(500000, new double[] {13548, 10200, 11860, 9771, 9535}, 10982.8, 1697.578481),
            row(600000, new double[] {15190, 11766, 12004, 11905, 12016}, 12576.2, 1464.592162),
            row(700000, new double[] {18699, 13990, 14145, 14631, 15613}, 15415.6, 1941.78006),
            row(800000, new double[] {21867, 17114, 16613, 16669, 16912}, 17835, 2262.831965),
            row(900000, new double[] {27573, 27515, 20079, 25135, 25244}, 25109.2, 3048.767489),
            row(1000000, new double[] {30133, 23856, 29773, 23409, 22944}, 26023, 3604.293481));

    private static final List<Row> ACTOR = List.of(
            row(16, new double[] {232, 252, 245, 178, 265}, 234.4, 33.70904923),
            row(100000, new double[] {10101, 9917, 9787, 10415, 10188}, 10081.6, 243.2772081),
            row(200000, new double[] {19561, 21550, 20462, 20760, 21043}, 20675.2, 740.7156674),
            row(300000, new double[] {28573, 29331, 29365, 27855, 29584}, 28941.6, 717.6599473),
            row(400000, new double[] {46005, 43765, 40593, 43841, 42645}, 43369.8, 1972.209725),
            row(500000, new double[] {56492, 56517, 60347, 52441, 55501}, 56259.6, 2827.732448),
            row(600000, new double[] {78241, 77622, 73488, 79494, 77525}, 77274, 2257.287642),
            row(700000, new double[] {90986, 89651, 85749, 85166, 87269}, 87764.2, 2499.845335),
            row(800000, new double[] {100236, 109246, 106318, 107066, 103333}, 105239.8, 3507.886144),
            row(900000, new double[] {124692, 120616, 119240, 123152, 122507}, 122041.4, 2142.166147),
            row(1000000, new double[] {138521, 140688, 136829, 143252, 132643}, 138386.6, 4012.532903));

    /** Table 4.4 row by row: hundreds of thousands, actor trials 1 and 2 and average, non-actor likewise. */
    private static final double[][] LARGE_PRINTED = {
        {0, 23, 26, 24.5, 669, 4416, 2542.5},
        {2, 38027, 18527, 28277, 3794, 8158, 5976},
        {4, 42565, 76530, 59547.5, 6878, 11662, 9270},
        {6, 66898, 72121, 69509.5, 15309, 15845, 15577},
        {8, 96540, 99068, 97804, 17577, 31445, 24511},
        {10, 129888, 137843, 133865.5, 22440, 38640, 30540},
        {12, 172992, 166116, 169554, 29002, 52032, 40517},
        {14, 218004, 214518, 216261, 61050, 36339, 48694.5},
        {16, 327169, 315567, 321368, 49437, 50330, 49883.5},
        {18, 361596, 344613, 353104.5, 73840, 41784, 57812},
        {20, 406120, 386807, 396463.5, 56560, 58972, 57766},
        {22, 424843, 429599, 427221, 68417, 67100, 67758.5},
        {24, 466301, 478751, 472526, 74645, 78079, 76362},
        {26, 508940, 504169, 506554.5, 83169, 82158, 82663.5},
        {28, 535457, 559071, 547264, 85585, 98517, 92051},
        {30, 604768, 596611, 600689.5, 149786, 138092, 143939},
    };

    private static final Map<EngineRole, List<Row>> LARGE = Map.of(
            EngineRole.ACTOR, largeColumn(1),
            EngineRole.NON_ACTOR, largeColumn(4));

    private static List<Row> largeColumn(int firstTrial) {
        return java.util.Arrays.stream(LARGE_PRINTED)
                .map(r -> row((int) r[0] * 100_000, new double[] {r[firstTrial], r[firstTrial + 1]}, r[firstTrial + 2], Double.NaN))
                .toList();
    }
}
