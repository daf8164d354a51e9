#pragma once
// Gear materials for the load capacity rating (ISO 6336-5:2016): the material classes of
// ISO 6336-5, their quality grades ML/MQ/ME, the endurance limits sigma_Hlim and sigma_FE as
// linear functions of the surface hardness, and a few named steels and irons as a designer
// orders them ("18CrNiMo7-6", "42CrMo4"). Stresses in MPa (N/mm^2), moduli in MPa.
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::gear {

/// Material classes of ISO 6336-5:2016, clause 5 (abbreviations of ISO 6336-1 Table 2 in brackets).
enum class MaterialClass {
  normalized_steel,        ///< normalized low-carbon wrought steel (St)
  cast_steel,              ///< cast steel (St)
  grey_cast_iron,          ///< grey cast iron (GG / GJL)
  nodular_cast_iron,       ///< nodular (ductile) cast iron, pearlitic or bainitic (GGG / GJS)
  through_hardened_carbon, ///< through-hardened (quenched and tempered) wrought carbon steel (V)
  through_hardened_alloy,  ///< through-hardened wrought alloy steel (V)
  case_carburized,         ///< case-hardened (carburized) wrought steel (Eh)
  induction_hardened,      ///< flame or induction hardened wrought steel, root hardened (IF)
  nitrided,                ///< nitriding steel, gas nitrided (NT)
  nitrided_through_hardened, ///< through-hardening steel, nitrided (NV nitr.)
  nitrocarburized,         ///< through-hardening steel, nitrocarburized (NV nitrocar.)
};

enum class QualityGrade { ML, MQ, ME };  ///< ISO 6336-5 clause 5.2: modest, normal industrial, highest

/// Everything the rating needs of one gear's material.
struct Material {
  std::string name;
  MaterialClass kind = MaterialClass::case_carburized;
  QualityGrade grade = QualityGrade::MQ;
  double hardness = 0;    ///< HV10 (HBW for the normalized and cast classes); 0 if not applicable
  double HB = 0;          ///< Brinell hardness used by AGMA and Z_W (HBW)
  double sigma_Hlim = 0;  ///< MPa, endurance limit for contact stress
  double sigma_Flim = 0;  ///< MPa, nominal stress number (bending); sigma_FE = 2 sigma_Flim (Y_ST = 2)
  double E = 206000;      ///< MPa, Young's modulus
  double nu = 0.3;        ///< Poisson's ratio
  double density = 7.83e-6;  ///< kg/mm^3 (ISO 6336-1 6.5.9: steel)
  double yield = 0;       ///< MPa, 0.2 % proof stress of the core (ISO 6336-3 Y_deltarelT), 0 = from the class
};

/// "St", "GG", "GGG", "V", "Eh", "IF", "NT", "NV(nitr)", "NV(nitrocar)" (ISO 6336-1 Table 2).
const char* abbreviation(MaterialClass kind);
/// "normalized-steel", "case-carburized", ... as in material names and YAML.
const char* to_string(MaterialClass kind);
const char* to_string(QualityGrade grade);

/// ISO 6336-5:2016 Figure 2-13 and Table 1: sigma_Hlim = A x + B for the class and grade at
/// hardness x (HV, or HBW for normalized and cast classes). The hardness is clamped to the
/// range of the figure. MPa.
double sigma_Hlim_of(MaterialClass kind, QualityGrade grade, double hardness);

/// ISO 6336-5:2016 Figure 2-13 and Table 1: sigma_Flim = A x + B (MPa); sigma_FE = 2 sigma_Flim.
double sigma_Flim_of(MaterialClass kind, QualityGrade grade, double hardness);

/// The hardness range [min, max] of the class in ISO 6336-5 (HV or HBW as above).
std::pair<double, double> hardness_range(MaterialClass kind);

/// A material of a class and grade at a hardness, with E and nu of the class (ISO 6336-2 Table 4).
Material material_of_class(MaterialClass kind, QualityGrade grade, double hardness, std::string name = "");

/// The named materials: "18CrNiMo7-6", "16MnCr5", "20MnCr5" (case-carburized, MQ, 60 HRC),
/// "42CrMo4" (through-hardened alloy, MQ, 300 HV), "34CrNiMo6" (through-hardened alloy, MQ,
/// 330 HV), "C45" (through-hardened carbon, MQ, 200 HV), "42CrMo4-induction" (IF, MQ, 560 HV),
/// "31CrMoV9-nitrided" (NT, MQ, 700 HV), "42CrMo4-nitrided" (NV nitr., MQ, 550 HV),
/// "S355" (normalized steel, MQ, 160 HBW), "GJL-250" (grey cast iron, MQ, 200 HBW),
/// "GJS-700" (nodular cast iron, MQ, 260 HBW); plus the class form
/// "CLASS:GRADE:HARDNESS" such as "through-hardened-alloy:MQ:300" (hardness in HV or HBW).
/// @throws std::invalid_argument with the list of known names when `name` is unknown or the
///         class form is malformed (unknown class or grade, hardness outside the class range).
Material material_by_name(std::string_view name);

/// Names of the table, for help texts and error messages.
std::vector<std::string> material_names();

/// Checks a user-defined material: sigma_Hlim, sigma_Flim, E > 0, 0 <= nu < 0.5, density > 0.
/// @throws std::invalid_argument naming the offending field.
void validate(const Material& material);

}  // namespace gearkit::gear
