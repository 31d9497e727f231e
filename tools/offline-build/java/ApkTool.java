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
 * Usage: ApkTool sign KEYSTORE PASSWORD ALIAS IN OUT MIN_SDK | ApkTool verify APK MIN_SDK
 */
public final class ApkTool {
    public static void main(String[] a) throws Exception {
        if (a[0].equals("sign")) {
            KeyStore ks = KeyStore.getInstance(KeyStore.getDefaultType());
            try (InputStream in = new FileInputStream(a[1])) { ks.load(in, a[2].toCharArray()); }
            PrivateKey key = (PrivateKey) ks.getKey(a[3], a[2].toCharArray());
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
