#pragma once
// The README's junior (1.45 m, 38 kg, female) as the library makes her from height, mass and
// sex: what `model new` and File > New athlete… must both give.

#include "saltus/use_cases/athlete_models.h"

namespace saltus::test {

inline BodyModel junior_athlete() {
  AthleteSize size;
  size.height_m = 1.45;
  size.mass_kg = 38.0;
  size.sex = Sex::kFemale;
  size.name = "junior";
  return new_athlete_model(size);
}

}  // namespace saltus::test
