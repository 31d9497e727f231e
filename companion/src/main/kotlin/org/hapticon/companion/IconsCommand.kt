package org.hapticon.companion

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson

/** `hapticon icons`: the presets as a JSON array in the icon-file schema, so any element can be saved as an icon file. */
fun runIcons(args: List<String>, console: Console) {
    Arguments.parse("icons", args).requireNoPositionals()
    console.out.println(IconJson.encodeList(HapticIcon.PRESETS, indent = "  "))
}
