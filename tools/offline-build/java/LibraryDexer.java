import com.android.tools.r8.ArchiveClassFileProvider;
import com.android.tools.r8.ClassFileResourceProvider;
import com.android.tools.r8.CompilationMode;
import com.android.tools.r8.D8;
import com.android.tools.r8.D8Command;
import com.android.tools.r8.DiagnosticsHandler;
import com.android.tools.r8.JdkClassFileProvider;
import com.android.tools.r8.OutputMode;
import com.android.tools.r8.ProgramResource;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;

/**
 * Dexes library jars one by one with D8, as AGP's dexing transform does for a debug build, then merges them: each
 * jar alone, in intermediate mode, its global synthetics (e.g. VarHandle desugaring) written apart so that the
 * merge makes each once. One JVM for all jars (one JIT warm-up, android.jar and the JDK opened once), `threads`
 * jars at a time. No jar needs the others on its classpath: with minSdk 24+ D8 does not desugar default or static
 * interface methods, the only desugaring that looks at other classes' hierarchy.
 *
 * usage: LibraryDexer MIN_API ANDROID_JAR JAVA_HOME THREADS JOBS_FILE MERGE_OUT
 *
 * JOBS_FILE holds `jar<TAB>dir` lines, in classpath order; a jar of `-` means `dir` already holds that jar's dex.
 * Each jar is dexed into a directory of its own beside `dir`, renamed to `dir` when D8 is done with it (classes*.dex,
 * and globals.zip when it needs global synthetics; a jar dexed is kept even if the build is stopped, and a `dir`
 * another process made first is left as it is: the same key, the same dex); "DONE i ms" or "FAIL i message" is
 * printed per job i (0-based line number) as it ends. Then every directory's dex files
 * are merged by D8, still in intermediate mode, into MERGE_OUT ("MERGED ms"); a class defined by two jars fails the
 * merge. A MERGE_OUT of `-` merges nothing (the app's own modules: each module's dex goes into the APK as it is, so
 * that a change re-dexes only that module). The global synthetics stay in each jar's globals.zip, for the build to
 * compile once with the app's. Exit 1 on any failure. Debug mode throughout, as AGP's debuggable variants.
 */
public final class LibraryDexer {
    public static void main(String[] args) throws Exception {
        int minApi = Integer.parseInt(args[0]);
        ClassFileResourceProvider androidJar = new Shared(new ArchiveClassFileProvider(Path.of(args[1])));
        ClassFileResourceProvider jdk = new Shared(JdkClassFileProvider.fromJdkHome(Path.of(args[2])));
        int threads = Integer.parseInt(args[3]);
        List<String[]> jobs = new ArrayList<>();
        for (String line : Files.readAllLines(Path.of(args[4]), StandardCharsets.UTF_8)) {
            if (!line.isBlank()) jobs.add(line.split("\t", 2));
        }
        Path mergeOut = args[5].equals("-") ? null : Path.of(args[5]);
        // D8 runs its own work (per class) on `inner`; the jars go `threads` at a time on `outer`, whose threads
        // only wait for D8, so the cores stay busy on the tail of a large jar as on many small ones.
        ExecutorService inner = Executors.newFixedThreadPool(threads);
        ExecutorService outer = Executors.newFixedThreadPool(threads);
        List<Future<Boolean>> results = new ArrayList<>();
        for (int i = 0; i < jobs.size(); i++) {
            int index = i;
            if (!jobs.get(i)[0].equals("-")) {
                results.add(outer.submit(() -> dex(index, jobs.get(index), minApi, androidJar, jdk, inner)));
            }
        }
        boolean ok = true;
        for (Future<Boolean> r : results) ok &= r.get();
        outer.shutdown();
        if (ok && mergeOut != null) ok = merge(jobs, mergeOut, minApi, inner);
        inner.shutdown();
        System.exit(ok ? 0 : 1);
    }

    private static boolean dex(int index, String[] job, int minApi, ClassFileResourceProvider androidJar,
                               ClassFileResourceProvider jdk, ExecutorService executor) {
        long start = System.nanoTime();
        Path done = Path.of(job[1]);
        Path out = done.resolveSibling(done.getFileName() + ".tmp" + ProcessHandle.current().pid());
        try {
            deleteTree(out);
            Files.createDirectories(out);
            D8Command command = D8Command.builder()
                    .addProgramFiles(Path.of(job[0]))
                    .addLibraryResourceProvider(androidJar)
                    .addLibraryResourceProvider(jdk)
                    .setMinApiLevel(minApi)
                    .setMode(CompilationMode.DEBUG)
                    .setIntermediate(true)
                    .setGlobalSyntheticsOutput(out.resolve("globals.zip"))
                    .setOutput(out, OutputMode.DexIndexed)
                    .build();
            D8.run(command, executor);
            try {
                Files.move(out, done, StandardCopyOption.ATOMIC_MOVE);
            } catch (FileAlreadyExistsException | DirectoryNotEmptyException e) {
                deleteTree(out);
            }
            report("DONE " + index + " " + (System.nanoTime() - start) / 1_000_000);
            return true;
        } catch (Throwable t) {
            try {
                deleteTree(out);
            } catch (IOException ignored) {
                // reported below; a leftover directory is replaced by the next run
            }
            report("FAIL " + index + " " + String.valueOf(t).replace('\n', ' '));
            return false;
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (Stream<Path> paths = Files.walk(dir)) {
            for (Path p : paths.sorted(Comparator.reverseOrder()).toList()) Files.delete(p);
        }
    }

    private static boolean merge(List<String[]> jobs, Path out, int minApi, ExecutorService executor) {
        long start = System.nanoTime();
        try {
            Files.createDirectories(out);
            // Still intermediate: the app's own dex may need the same global synthetics, so they are compiled
            // once for both afterwards (globals.zip of every jar, collected by the build).
            D8Command.Builder builder = D8Command.builder()
                    .setMinApiLevel(minApi)
                    .setMode(CompilationMode.DEBUG)
                    .setIntermediate(true)
                    .setOutput(out, OutputMode.DexIndexed);
            for (String[] job : jobs) {
                Path dir = Path.of(job[1]);
                try (Stream<Path> files = Files.list(dir)) {
                    files.filter(p -> p.getFileName().toString().matches("classes\\d*\\.dex")).sorted()
                            .forEach(builder::addProgramFiles);
                }
            }
            D8.run(builder.build(), executor);
            report("MERGED " + (System.nanoTime() - start) / 1_000_000);
            return true;
        } catch (Throwable t) {
            report("FAIL merge " + String.valueOf(t).replace('\n', ' '));
            return false;
        }
    }

    /**
     * A library provider that every D8 run shares: D8 calls `finished` on its providers when it ends, which closes
     * an archive's zip file under the runs still reading it, so this one ignores that and the JVM's exit closes it.
     */
    private record Shared(ClassFileResourceProvider provider) implements ClassFileResourceProvider {
        @Override
        public Set<String> getClassDescriptors() {
            return provider.getClassDescriptors();
        }

        @Override
        public ProgramResource getProgramResource(String descriptor) {
            return provider.getProgramResource(descriptor);
        }

        @Override
        public void finished(DiagnosticsHandler handler) {
        }
    }

    private static synchronized void report(String line) {
        System.out.println(line);
        System.out.flush();
    }
}
