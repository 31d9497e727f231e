import java.io.File;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.runner.Description;
import org.junit.runner.JUnitCore;
import org.junit.runner.Request;
import org.junit.runner.Result;
import org.junit.runner.RunWith;
import org.junit.runner.manipulation.Filter;
import org.junit.runner.notification.Failure;
import org.junit.runner.notification.RunListener;

/**
 * Runs every JUnit 4 test class found in a directory of compiled test classes.
 * Usage: TestMain CLASSES_DIR [NAME_REGEX]. Prints failures as they happen and, last,
 * a machine-readable line "TESTS passed=N failed=N skipped=N" that the build sums across modules.
 */
public final class TestMain {
    public static void main(String[] args) throws Exception {
        File root = new File(args[0]);
        Pattern only = args.length > 1 ? Pattern.compile(args[1]) : null;
        List<Class<?>> classes = new ArrayList<>();
        collect(root, root, classes);
        // hapticon.test.sdk36 = "only" | "without": the classes whose Robolectric @Config asks for SDK 36 or later run in
        // a JVM of their own (SDK 36's framework is Java 21 bytecode), the rest in the build's JDK.
        String sdk36 = System.getProperty("hapticon.test.sdk36");
        if (sdk36 != null) classes.removeIf(c -> asksForSdk36(c) != sdk36.equals("only"));
        classes.sort((a, b) -> a.getName().compareTo(b.getName()));
        JUnitCore core = new JUnitCore();
        core.addListener(new RunListener() {
            @Override public void testFailure(Failure f) {
                System.out.println("FAILED " + f.getDescription().getDisplayName());
                String trace = f.getTrace();
                String[] lines = trace.split("\n");
                StringBuilder shown = new StringBuilder();
                // The message and the frames above the test framework's: the part worth reading.
                for (int i = 0; i < lines.length && i < 30; i++) {
                    if (i > 0 && lines[i].contains("at org.junit.") || lines[i].contains("at jdk.internal.reflect.")) break;
                    shown.append("    ").append(lines[i]).append('\n');
                }
                System.out.print(shown);
            }
            @Override public void testAssumptionFailure(Failure f) {
                System.out.println("SKIPPED " + f.getDescription().getDisplayName() + ": " + f.getMessage());
            }
        });
        Request request = Request.classes(classes.toArray(new Class<?>[0]));
        if (only != null) {
            request = request.filterWith(new Filter() {
                @Override public boolean shouldRun(Description d) {
                    return d.getMethodName() == null || only.matcher(d.getClassName() + "." + d.getMethodName()).find();
                }
                @Override public String describe() { return "tests matching " + only; }
            });
        }
        org.junit.runner.Runner runner = request.getRunner();
        if (only != null && runner instanceof org.junit.internal.runners.ErrorReportingRunner) {
            // The filter matched nothing in this module: not a failure.
            System.out.println("TESTS passed=0 failed=0 skipped=0 classes=0 seconds=0");
            System.exit(0);
        }
        Result r = core.run(runner);
        int failed = r.getFailureCount();
        int skipped = r.getIgnoreCount() + r.getAssumptionFailureCount();
        int passed = r.getRunCount() - failed - r.getAssumptionFailureCount();
        System.out.println("TESTS passed=" + passed + " failed=" + failed + " skipped=" + skipped
                + " classes=" + classes.size() + " seconds=" + r.getRunTime() / 1000.0);
        System.exit(failed == 0 ? 0 : 1);
    }

    /** Whether [c]'s Robolectric @Config (read by name: no Robolectric on this class's classpath) names an SDK ≥ 36. */
    static boolean asksForSdk36(Class<?> c) {
        for (java.lang.annotation.Annotation a : c.getAnnotations()) {
            if (!a.annotationType().getName().equals("org.robolectric.annotation.Config")) continue;
            try {
                for (int sdk : (int[]) a.annotationType().getMethod("sdk").invoke(a)) if (sdk >= 36) return true;
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException(e);
            }
        }
        return false;
    }

    private static void collect(File root, File dir, List<Class<?>> out) throws Exception {
        File[] files = dir.listFiles();
        if (files == null) return;
        for (File f : files) {
            if (f.isDirectory()) { collect(root, f, out); continue; }
            String rel = root.toPath().relativize(f.toPath()).toString();
            if (!rel.endsWith(".class") || rel.contains("$")) continue;
            String name = rel.substring(0, rel.length() - 6).replace(File.separatorChar, '.');
            Class<?> c = Class.forName(name, false, TestMain.class.getClassLoader());
            if (isTestClass(c)) out.add(c);
        }
    }

    private static boolean isTestClass(Class<?> c) {
        if (!Modifier.isPublic(c.getModifiers()) || Modifier.isAbstract(c.getModifiers()) || c.isInterface()) return false;
        if (c.isAnnotationPresent(RunWith.class)) return true;
        for (Method m : c.getMethods()) if (m.isAnnotationPresent(org.junit.Test.class)) return true;
        return false;
    }
}
