#pragma once
// Conversions between cgs, nuclear units (MeV, fm) and Remnant's code units G = c = M_sun = 1
// (temperature stays in MeV). One place for every constant so that all readers agree bit-for-bit.
namespace remnant::units {

// Exact SI-defined constants.
inline constexpr double c_cgs = 2.99792458e10;             // cm/s
inline constexpr double c2_cgs = c_cgs * c_cgs;            // cm^2/s^2
inline constexpr double MeV_in_erg = 1.602176634e-6;       // erg
// CODATA 2018 listed value of (1 MeV)/c^2 in g (the table converters use this rounding).
inline constexpr double MeV_c2_in_g = 1.782661921e-27;
inline constexpr double fm3_in_cm3 = 1e-39;                // cm^3
inline constexpr double G_cgs = 6.67430e-8;                // cm^3 g^-1 s^-2 (CODATA 2018)
inline constexpr double GMsun_cgs = 1.3271244e26;          // cm^3 s^-2 (IAU 2015 nominal)
inline constexpr double Msun_g = GMsun_cgs / G_cgs;        // g

// Code units: the length, time, density, pressure units in cgs.
inline constexpr double length_cm = GMsun_cgs / c2_cgs;                   // ~1.4766e5 cm
inline constexpr double time_s = length_cm / c_cgs;                       // ~4.9255e-6 s
inline constexpr double density_cgs = Msun_g / (length_cm * length_cm * length_cm);  // g/cm^3
inline constexpr double pressure_cgs = density_cgs * c2_cgs;              // dyn/cm^2 = erg/cm^3
inline constexpr double specific_energy_cgs = c2_cgs;                     // erg/g

// Multiply a cgs value by these to get code units.
inline constexpr double rho_cgs_to_code = 1.0 / density_cgs;
inline constexpr double press_cgs_to_code = 1.0 / pressure_cgs;
inline constexpr double eps_cgs_to_code = 1.0 / specific_energy_cgs;
inline constexpr double cs2_cgs_to_code = 1.0 / c2_cgs;

// Nuclear units (number density in fm^-3, energy density in MeV/fm^3) to code units.
inline constexpr double MeV_fm3_to_code_press = MeV_in_erg / fm3_in_cm3 * press_cgs_to_code;
// Mass density of nb [fm^-3] baryons of mass m [MeV]: rho_code = nb * m * mass_fm3_to_code_rho.
inline constexpr double MeV_fm3_mass_to_code_rho = MeV_c2_in_g / fm3_in_cm3 * rho_cgs_to_code;

// A neutron mass in MeV used when a table does not give its own.
inline constexpr double neutron_mass_MeV = 939.56535;

}  // namespace remnant::units
