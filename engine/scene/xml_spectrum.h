// <spectrum> and Mitsuba 0.x's <blackbody> as linear sRGB, read the way Mitsuba 3's RGB variants
// load them (the conversion itself is scene/spectrum.h):
//  - value="v": a single value;
//  - value="nm:v, nm:v, ...": at least two samples at increasing wavelengths;
//  - type="irregular" (wavelengths, values), type="regular" (wavelength_min, wavelength_max,
//    values) and type="blackbody" (temperature, wavelength_min, wavelength_max): Mitsuba 3's RGB
//    variants load these plugins but cannot evaluate them; gdrender converts their spectrum as
//    it converts an inline list (from which the spectral variants build the same plugins);
//  - <blackbody temperature="5000K" scale="s"/> (Mitsuba 0.x): that colour at luminance s.
// Wavelengths and values must be finite and values not negative (InputError naming file and
// line). A colour that Mitsuba clamps (a reflectance into [0, 1], anything else to >= 0) is
// clamped the same way, with a warning naming file and line in doc.warnings.
#pragma once
#include "scene/spectrum.h"
#include "scene/xml_document.h"

namespace gdr {

Rgb parse_spectrum(const XmlNode& node, const XmlDocument& doc, SpectrumUse use);

}  // namespace gdr
