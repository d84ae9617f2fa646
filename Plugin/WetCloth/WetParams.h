#pragma once
// Parameters of the wetting model (paper Section 4, Table 1). Declared once,
// with units, ranges and descriptions, in WetClothPlugin.cpp.
namespace soak::wet {

enum class DiffusionForm { Conservative = 0, Literal = 1 };

struct WetParams {
  float sMax = 0.4f;           // S^MAX (Eq. 10)
  float sEW = 0.35f;           // S^EW: emission threshold (Section 4.4)
  float sT = 0.12f;            // S^T = 0.3 S^MAX (Section 4.5)
  float c = 0.001f;            // Eq. 10: S = c m_water / V (m^3/kg; 1/rho_water makes S a volume fraction)
  float kappaA = 0.1f;         // absorption rate (Eq. 11)
  float etaA = 0.4f;           // gravity influence on absorption (Eq. 11)
  float kappaD = 0.5f;         // diffusion rate (Eq. 12)
  float etaD = 0.6f;           // gravity influence on diffusion (Eq. 12)
  float kappaS = 0.8f;         // saturation smoothing rate (Eq. 17)
  float epsilon = 0.1f;        // Eq. 15 relaxation, relative to (sum_j a_ij)^2
  int diffusionIterations = 1;
  DiffusionForm form = DiffusionForm::Conservative;
  float beta = 10.f;           // Eq. 18; see Doc/model.md
  float mThreshold = 0.002f;   // drip mass (kg)
  float kappaE = 10.f;         // Eq. 19 attraction (m/s^2)
  float etaE = 0.02f;          // Eq. 19 saturation weight (kg)
  float kappaAd = 0.3f;        // Eq. 20 (N)
  float etaAd = -1.f;          // Eq. 20 (N); < 0: kappaAd * S^T^2 (no pull between dry particles)
  float clothRestDensity = 800.f;  // Table 1, for Psi of Eq. 19
  bool emission = true, sticking = true, wetWeight = true;
};

}  // namespace soak::wet
