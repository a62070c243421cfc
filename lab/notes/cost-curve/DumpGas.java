import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The initial state of a gas scene (equal discs, periodic box) as the C port of lab/notes/fast-vs-c reads
 * it: N (int32), width, height, radius, inverse mass, until (doubles), then x, y, vx, vy (N doubles each),
 * all little-endian. The same discs carom generates from the scene, so both codes start from one state.
 *
 * <p>Not part of the build: {@code java -cp app/target/carom.jar lab/notes/cost-curve/DumpGas.java SCENE.json OUT.bin}
 */
public final class DumpGas {
    public static void main(String[] args) throws IOException {
        Scene scene = SceneReader.read(Path.of(args[0]));
        Discs d = scene.newDiscs();
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(Path.of(args[1])), 1 << 20)) {
            ByteBuffer head = ByteBuffer.allocate(4 + 5 * 8).order(ByteOrder.LITTLE_ENDIAN);
            head.putInt(d.n).putDouble(scene.box().width()).putDouble(scene.box().height())
                    .putDouble(d.radius[0]).putDouble(d.invMass[0]).putDouble(scene.until());
            out.write(head.array());
            ByteBuffer block = ByteBuffer.allocate(8 * 4096).order(ByteOrder.LITTLE_ENDIAN);
            for (double[] column : new double[][] {d.x, d.y, d.vx, d.vy}) {
                for (int i = 0; i < d.n; i++) {
                    if (!block.hasRemaining()) {
                        out.write(block.array(), 0, block.position());
                        block.clear();
                    }
                    block.putDouble(column[i]);
                }
                out.write(block.array(), 0, block.position());
                block.clear();
            }
        }
    }
}
