import carom.core.scene.*;
import java.nio.file.Path;
public class Read {
  public static void main(String[] a) {
    for (int r = 0; r < Integer.parseInt(a[1]); r++) {
      System.gc();
      long t0 = System.nanoTime();
      Scene s = SceneReader.read(Path.of(a[0]));
      long t1 = System.nanoTime();
      System.out.printf("read %.0f ms (%d discs)%n", (t1-t0)/1e6, s.newDiscs().n);
    }
  }
}
