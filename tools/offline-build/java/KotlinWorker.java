import java.io.FileOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jetbrains.kotlin.cli.common.ExitCode;
import org.jetbrains.kotlin.cli.jvm.K2JVMCompiler;

/**
 * Keeps one warm Kotlin compiler for a whole build: each line on stdin names an argument file
 * (one argument per line); diagnostics go to ARGFILE.log and "EXIT n" is printed when it is done.
 * Saves the JVM start and JIT warm-up that a kotlinc process per module would pay again and again.
 */
public final class KotlinWorker {
    public static void main(String[] ignored) throws Exception {
        java.io.BufferedReader in = new java.io.BufferedReader(new java.io.InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            if (line.isBlank()) continue;
            List<String> args = Files.readAllLines(Path.of(line), StandardCharsets.UTF_8);
            int code;
            try (PrintStream log = new PrintStream(new FileOutputStream(line + ".log"), true, StandardCharsets.UTF_8)) {
                try {
                    ExitCode exit = new K2JVMCompiler().exec(log, args.toArray(new String[0]));
                    code = exit.getCode();
                } catch (Throwable t) {
                    t.printStackTrace(log);
                    code = 3;
                }
            }
            System.out.println("EXIT " + code);
            System.out.flush();
        }
    }
}
