package carom.app.animate;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.FileImageOutputStream;
import javax.imageio.stream.ImageOutputStream;

/**
 * An animated GIF written frame by frame with the JDK's GIF writer (javax.imageio), each frame going
 * to the file as it comes, so memory does not grow with the number of frames. Every frame shows for
 * the same delay; the first carries the NETSCAPE2.0 application extension that makes viewers loop
 * forever, and a comment (what made the file). The writer reduces each RGB frame to a palette of its
 * own (at most 256 colours).
 */
final class GifSequence implements AutoCloseable {
    private static final String FORMAT = "javax_imageio_gif_image_1.0";

    private final ImageOutputStream out;
    private final ImageWriter writer;
    private final int delayCentiseconds;
    private final String comment;
    private long frames;

    private GifSequence(ImageOutputStream out, ImageWriter writer, int delayCentiseconds, String comment) {
        this.out = out;
        this.writer = writer;
        this.delayCentiseconds = delayCentiseconds;
        this.comment = comment;
    }

    /** Starts a GIF in {@code file} (created or replaced) whose frames each show {@code delayCentiseconds}. */
    static GifSequence create(Path file, int delayCentiseconds, String comment) throws IOException {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
        Files.deleteIfExists(file);
        // Created here, not by ImageIO.createImageOutputStream: that one prints the stack trace of a file
        // it cannot open to System.err and returns null, where Files says why (permission denied, ...).
        Files.createFile(file);
        ImageOutputStream out = new FileImageOutputStream(file.toFile());
        writer.setOutput(out);
        writer.prepareWriteSequence(null);
        return new GifSequence(out, writer, delayCentiseconds, comment);
    }

    /** Appends one frame. */
    void add(BufferedImage frame) throws IOException {
        IIOMetadata metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(frame), null);
        IIOMetadataNode root = new IIOMetadataNode(FORMAT);
        IIOMetadataNode control = new IIOMetadataNode("GraphicControlExtension");
        control.setAttribute("disposalMethod", "none");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", "FALSE");
        control.setAttribute("delayTime", Integer.toString(delayCentiseconds));
        control.setAttribute("transparentColorIndex", "0");
        root.appendChild(control);
        if (frames == 0) {
            IIOMetadataNode applications = new IIOMetadataNode("ApplicationExtensions");
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0}); // sub-block 1: loop count 0, that is forever
            applications.appendChild(loop);
            root.appendChild(applications);
            if (comment != null && !comment.isEmpty()) {
                IIOMetadataNode comments = new IIOMetadataNode("CommentExtensions");
                IIOMetadataNode text = new IIOMetadataNode("CommentExtension");
                text.setAttribute("value", comment);
                comments.appendChild(text);
                root.appendChild(comments);
            }
        }
        metadata.mergeTree(FORMAT, root);
        writer.writeToSequence(new IIOImage(frame, null, metadata), null);
        frames++;
    }

    long frames() {
        return frames;
    }

    /** Ends the GIF (its trailer) when at least one frame was written, and releases the file. */
    @Override
    public void close() throws IOException {
        try {
            if (frames > 0) {
                writer.endWriteSequence();
            }
        } finally {
            writer.dispose();
            out.close();
        }
    }
}
