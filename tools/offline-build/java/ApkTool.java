import com.android.apksig.ApkSigner;
import com.android.apksig.ApkVerifier;
import java.io.File;
import java.io.FileInputStream;
import java.io.InputStream;
import java.security.KeyStore;
import java.security.PrivateKey;
import java.security.cert.X509Certificate;
import java.util.List;

/**
 * Signs (and aligns) or verifies an APK with apksig, the library apksigner and AGP use.
 * Usage: ApkTool sign KEYSTORE PASSWORD ALIAS IN OUT MIN_SDK [KEY_PASSWORD] | ApkTool verify APK MIN_SDK
 * A password written env:NAME is read from the environment variable NAME (release keys stay out of argv).
 */
public final class ApkTool {
    private static char[] secret(String arg) {
        if (!arg.startsWith("env:")) return arg.toCharArray();
        String value = System.getenv(arg.substring(4));
        if (value == null) throw new IllegalArgumentException("environment variable " + arg.substring(4) + " is not set");
        return value.toCharArray();
    }

    public static void main(String[] a) throws Exception {
        if (a[0].equals("sign")) {
            char[] storePassword = secret(a[2]);
            char[] keyPassword = a.length > 7 ? secret(a[7]) : storePassword;
            KeyStore ks = KeyStore.getInstance(KeyStore.getDefaultType());
            try (InputStream in = new FileInputStream(a[1])) { ks.load(in, storePassword); }
            PrivateKey key = (PrivateKey) ks.getKey(a[3], keyPassword);
            if (key == null) throw new IllegalArgumentException("no key " + a[3] + " in " + a[1]);
            X509Certificate cert = (X509Certificate) ks.getCertificate(a[3]);
            ApkSigner.SignerConfig signer = new ApkSigner.SignerConfig.Builder("CERT", key, List.of(cert)).build();
            new ApkSigner.Builder(List.of(signer))
                    .setInputApk(new File(a[4])).setOutputApk(new File(a[5]))
                    .setMinSdkVersion(Integer.parseInt(a[6]))
                    .setV1SigningEnabled(false).setV2SigningEnabled(true).setV3SigningEnabled(true)
                    .build().sign();
        } else if (a[0].equals("verify")) {
            ApkVerifier.Result r = new ApkVerifier.Builder(new File(a[1]))
                    .setMinCheckedPlatformVersion(Integer.parseInt(a[2])).build().verify();
            for (ApkVerifier.IssueWithParams e : r.getErrors()) System.out.println("ERROR " + e);
            System.out.println("verified=" + r.isVerified() + " v2=" + r.isVerifiedUsingV2Scheme()
                    + " v3=" + r.isVerifiedUsingV3Scheme() + " signers=" + r.getSignerCertificates().size());
            System.exit(r.isVerified() ? 0 : 1);
        } else {
            throw new IllegalArgumentException("usage: ApkTool sign|verify ...");
        }
    }
}
