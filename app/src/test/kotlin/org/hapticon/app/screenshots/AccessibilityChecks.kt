package org.hapticon.app.screenshots

import android.graphics.Bitmap
import androidx.compose.ui.geometry.Rect
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.semantics.SemanticsNode
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.semantics.getOrNull
import androidx.compose.ui.text.TextLayoutResult
import androidx.compose.ui.text.font.FontWeight
import com.google.android.apps.common.testing.accessibility.framework.AccessibilityCheckResult.AccessibilityCheckResultType
import com.google.android.apps.common.testing.accessibility.framework.AccessibilityHierarchyCheck
import com.google.android.apps.common.testing.accessibility.framework.AccessibilityHierarchyCheckResult
import com.google.android.apps.common.testing.accessibility.framework.Parameters
import com.google.android.apps.common.testing.accessibility.framework.checks.ImageContrastCheck
import com.google.android.apps.common.testing.accessibility.framework.checks.SpeakableTextPresentCheck
import com.google.android.apps.common.testing.accessibility.framework.checks.TextContrastCheck
import com.google.android.apps.common.testing.accessibility.framework.checks.TouchTargetSizeCheck
import com.google.android.apps.common.testing.accessibility.framework.uielement.AccessibilityHierarchyAndroid
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.AccessibilityHierarchyProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.DeviceStateProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.DisplayInfoMetricsProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.DisplayInfoProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.ViewElementClassNamesProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.ViewHierarchyElementProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AccessibilityHierarchyProtos.WindowHierarchyElementProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AndroidFrameworkProtos.CharSequenceProto
import com.google.android.apps.common.testing.accessibility.framework.uielement.proto.AndroidFrameworkProtos.RectProto
import com.google.android.apps.common.testing.accessibility.framework.utils.contrast.BitmapImage
import kotlin.math.roundToInt

/**
 * Google's Accessibility Test Framework (ATF) checks, run on a Compose screen.
 *
 * ATF 3.1 (the newest on Maven Central) walks Android Views; it does not see inside a ComposeView. So the
 * unmerged Compose semantics tree (pass `onRoot(useUnmergedTree = true)`) is translated into ATF's own
 * hierarchy format (`AccessibilityHierarchyProto`, the format ATF itself serialises hierarchies to) with the
 * classes a View-based screen would report (a clickable node is a Button, text is a TextView, a switch a
 * CompoundButton…), and ATF's checks then run unchanged on it together with the rendered bitmap. Unmerged,
 * as Views are: ATF reads a control's name from its non-focusable children as TalkBack does, and measures
 * each text's contrast within the text's own bounds (a merged button's bounds would include its outline):
 * - [TouchTargetSizeCheck]: every clickable target at least 48×48 dp (ATF's threshold);
 * - [SpeakableTextPresentCheck]: every control has text or a content description;
 * - [TextContrastCheck] / [ImageContrastCheck]: WCAG contrast (4.5:1 text, 3:1 large text and images),
 *   measured on the screenshot's pixels.
 * See [fails] for which results fail a test.
 */
object AccessibilityChecks {
    private val checks: List<AccessibilityHierarchyCheck> = listOf(
        TouchTargetSizeCheck(), SpeakableTextPresentCheck(), TextContrastCheck(), ImageContrastCheck(),
    )

    /**
     * ERROR results fail, and so do the contrast checks' "not sufficient" results: ATF reports a contrast
     * measured from screenshot pixels as a WARNING (a heuristic), but here the screenshot is exactly what
     * the phone draws. Borderline contrast and other warnings are left to the reviewer.
     */
    private fun fails(check: AccessibilityHierarchyCheck, result: AccessibilityHierarchyCheckResult): Boolean =
        result.type == AccessibilityCheckResultType.ERROR ||
            result.type == AccessibilityCheckResultType.WARNING && when (check) {
                is TextContrastCheck -> result.resultId == TextContrastCheck.RESULT_ID_TEXTVIEW_HEURISTIC_CONTRAST_NOT_SUFFICIENT
                is ImageContrastCheck -> result.resultId == ImageContrastCheck.RESULT_ID_IMAGE_CONTRAST_NOT_SUFFICIENT
                else -> false
            }

    /** The failing results as one line each (check, message, the element's text), empty when all pass. */
    fun run(root: SemanticsNode, screenshot: Bitmap, touchTargetDp: Int = 48): List<String> {
        val hierarchy = AccessibilityHierarchyAndroid.newBuilder(hierarchyProto(root, screenshot)).build()
        val parameters = Parameters().apply {
            putScreenCapture(BitmapImage(screenshot))
            if (touchTargetDp != 48) putCustomTouchTargetSize(touchTargetDp)
        }
        return checks.flatMap { check ->
            check.runCheckOnHierarchy(hierarchy, null, parameters)
                .filter { fails(check, it) }
                .map { result ->
                    val element = result.element
                    val label = element?.text ?: element?.contentDescription ?: ""
                    // ATF's messages come from a resource bundle in the AAR's assets, which a JVM test does not
                    // load; the result id and its metadata (sizes, colours, ratios) say the same.
                    "${check.javaClass.simpleName}: ${result.type} #${result.resultId} ${result.metadata} " +
                        "[\"$label\" at ${element?.boundsInScreen}]"
                }
        }
    }

    /** Classes in the order of their ids; every element lists its class and superclasses by id. */
    private val classChains = mapOf(
        "android.view.View" to listOf("android.view.View"),
        "android.view.ViewGroup" to listOf("android.view.ViewGroup", "android.view.View"),
        "android.widget.TextView" to listOf("android.widget.TextView", "android.view.View"),
        "android.widget.Button" to listOf("android.widget.Button", "android.widget.TextView", "android.view.View"),
        "android.widget.EditText" to listOf("android.widget.EditText", "android.widget.TextView", "android.view.View"),
        "android.widget.ImageView" to listOf("android.widget.ImageView", "android.view.View"),
        "android.widget.CompoundButton" to
            listOf("android.widget.CompoundButton", "android.widget.Button", "android.widget.TextView", "android.view.View"),
        "android.widget.SeekBar" to listOf("android.widget.SeekBar", "android.widget.ProgressBar", "android.view.View"),
    )
    private val classIds: Map<String, Int> =
        classChains.values.flatten().distinct().withIndex().associate { (i, name) -> name to i }

    private fun hierarchyProto(root: SemanticsNode, screenshot: Bitmap): AccessibilityHierarchyProto {
        val density = root.layoutInfo.density.density
        val screen = Rect(0f, 0f, screenshot.width.toFloat(), screenshot.height.toFloat())
        val window = WindowHierarchyElementProto.newBuilder().setId(0).setWindowId(0).setType(1).setLayer(0)
            .setFocused(true).setBoundsInScreen(rect(screen))
        var nextId = 0
        // A disabled control disables its text too (unmerged, the Text is a child of the Button): WCAG 1.4.3
        // exempts inactive components from contrast, and ATF skips disabled elements.
        fun add(node: SemanticsNode, parentId: Int?, parentDisabled: Boolean): Int {
            val id = nextId++
            val disabled = parentDisabled || node.config.contains(SemanticsProperties.Disabled)
            val builder = element(node, id, parentId, screen, density).setEnabled(!disabled)
            val index = window.viewsCount
            window.addViews(builder)
            val childIds = node.children.map { add(it, id, disabled) }
            window.setViews(index, window.getViews(index).toBuilder().addAllChildIds(childIds))
            return id
        }
        add(root, null, parentDisabled = false)
        val metrics = DisplayInfoMetricsProto.newBuilder().setDensity(density).setScaledDensity(density)
            .setDensityDpi((density * 160).roundToInt()).setWidthPixels(screenshot.width)
            .setHeightPixels(screenshot.height).setXDpi(density * 160).setYDpi(density * 160)
        return AccessibilityHierarchyProto.newBuilder()
            .setDeviceState(
                DeviceStateProto.newBuilder().setSdkVersion(35).setLocale("en_US").setDefaultDisplayInfo(
                    DisplayInfoProto.newBuilder().setMetricsWithoutDecoration(metrics).setRealMetrics(metrics),
                ),
            )
            .addWindows(window)
            .setActiveWindowId(0)
            .setViewElementClassNames(ViewElementClassNamesProto.newBuilder().putAllClassName(classIds))
            .build()
    }

    private fun element(node: SemanticsNode, id: Int, parentId: Int?, screen: Rect, density: Float): ViewHierarchyElementProto.Builder {
        val config = node.config
        val text = config.getOrNull(SemanticsProperties.EditableText)?.text
            ?: config.getOrNull(SemanticsProperties.Text)?.joinToString(" ") { it.text }
        val description = config.getOrNull(SemanticsProperties.ContentDescription)?.joinToString(" ")
        val clickable = config.getOrNull(SemanticsActions.OnClick) != null
        val longClickable = config.getOrNull(SemanticsActions.OnLongClick) != null
        val toggleable = config.getOrNull(SemanticsProperties.ToggleableState) != null
        val editable = config.getOrNull(SemanticsActions.SetText) != null
        val adjustable = config.getOrNull(SemanticsActions.SetProgress) != null
        val role = config.getOrNull(SemanticsProperties.Role)
        val className = when {
            editable -> "android.widget.EditText"
            adjustable -> "android.widget.SeekBar"
            toggleable -> "android.widget.CompoundButton"
            clickable -> "android.widget.Button"
            role == Role.Image -> "android.widget.ImageView"
            text != null -> "android.widget.TextView"
            node.children.isNotEmpty() -> "android.view.ViewGroup"
            else -> "android.view.View"
        }
        // A control's touch area as Compose reports it: Compose widens every target to ViewConfiguration's
        // minimumTouchTargetSize (48 dp) and the phone honours that, so this catches a platform or
        // configuration that does not (AccessibilityChecksTest proves the measurement with a 56 dp rule).
        val bounds = if (clickable || toggleable || adjustable) node.touchBoundsInRoot else node.boundsInRoot
        val visible = bounds.overlaps(screen) && bounds.width > 0f && bounds.height > 0f
        val builder = ViewHierarchyElementProto.newBuilder()
            .setId(id)
            .setClassName(className)
            .setAccessibilityClassName(className)
            .addAllSuperclasses(classChains.getValue(className).map { classIds.getValue(it) })
            .setPackageName("org.hapticon.app")
            .setBoundsInScreen(rect(bounds.intersect(screen)))
            .setNonclippedWidth(bounds.width.roundToInt())
            .setNonclippedHeight(bounds.height.roundToInt())
            .setVisibleToUser(visible)
            .setImportantForAccessibility(
                text != null || description != null || clickable || toggleable || editable || adjustable,
            )
            .setClickable(clickable || toggleable)
            .setLongClickable(longClickable)
            .setFocusable(clickable || toggleable || editable || adjustable || config.isMergingSemanticsOfDescendants)
            .setEditable(editable)
            .setCheckable(toggleable)
            .setDrawingOrder(id)
        // A scrolling container says which way it can still scroll, as a View reports canScrollVertically: ATF
        // (ViewHierarchyElement.isAgainstScrollableEdge) then treats a control cut by the container's edge as
        // partly scrolled away and does not measure its touch target (TouchTargetSizeCheck demotes it to
        // NOT_RUN), instead of failing the chip of a bubble half under the top bar.
        scrollDirections(node)?.let { (backward, forward) ->
            builder.setScrollable(backward || forward).setCanScrollBackward(backward).setCanScrollForward(forward)
        }
        parentId?.let { builder.setParentId(it) }
        text?.let { builder.setText(CharSequenceProto.newBuilder().setText(it)) }
        description?.let { builder.setContentDescription(CharSequenceProto.newBuilder().setText(it)) }
        textStyle(node, density)?.let { (sizePx, bold) ->
            builder.setTextSize(sizePx)
            builder.setTypefaceStyle(if (bold) 1 else 0)
        }
        return builder
    }

    /**
     * Whether [node] can still scroll towards the top/left (ATF's "backward") and towards the bottom/right
     * ("forward") on screen, or null when it does not scroll. A reversed range (a chat list anchored at the
     * bottom) scrolls its value up the screen, so the directions swap.
     */
    private fun scrollDirections(node: SemanticsNode): Pair<Boolean, Boolean>? {
        val range = node.config.getOrNull(SemanticsProperties.VerticalScrollAxisRange)
            ?: node.config.getOrNull(SemanticsProperties.HorizontalScrollAxisRange)
            ?: return null
        val value = range.value()
        val towardsStart = value > 0f
        val towardsEnd = value < range.maxValue()
        return if (range.reverseScrolling) towardsEnd to towardsStart else towardsStart to towardsEnd
    }

    /** The first text layout's font size in px and whether it is bold (ATF's large-text rule uses both). */
    private fun textStyle(node: SemanticsNode, density: Float): Pair<Float, Boolean>? {
        val layouts = mutableListOf<TextLayoutResult>()
        node.config.getOrNull(SemanticsActions.GetTextLayoutResult)?.action?.invoke(layouts)
        val style = layouts.firstOrNull()?.layoutInput?.style ?: return null
        val fontScale = node.layoutInfo.density.fontScale
        val size = style.fontSize.takeIf { it.isSp }?.value ?: return null
        val bold = (style.fontWeight ?: FontWeight.Normal) >= FontWeight.Bold
        return size * fontScale * density to bold
    }

    private fun rect(r: Rect): RectProto.Builder = RectProto.newBuilder()
        .setLeft(r.left.roundToInt()).setTop(r.top.roundToInt())
        .setRight(r.right.roundToInt()).setBottom(r.bottom.roundToInt())
}
