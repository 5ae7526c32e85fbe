/// de Leva 1996, Table 4 (J. Biomech. 29(9):1223-1230), the rows Saltus uses, both sexes.
/// Read from two independent open copies that agree on every value below except where noted:
/// the `deleva.m` lookup table of R. Gurchiek (2018) and the BMClab `BSPmale_ZdeLeva.txt` /
/// `BSPfemale_ZdeLeva.txt` tables of M. Duarte (lengths: Gurchiek's, the male ones also in the
/// HeiMan model of Heidelberg). Where open copies disagree (docs/method.md, "Athletes' body
/// models"): the female head mass is 6.68 % here (biorbd's DeLevaTable has 6.69); the female
/// foot's longitudinal radius is 13.9 % here (biorbd has the male 12.4).

#include "saltus/body/de_leva_table.h"

#include <stdexcept>

namespace saltus {

namespace {

using P = DeLevaPart;

// clang-format off
const std::vector<DeLevaRow> kMale = {
    //  part             name            from    to      mm     mass%  CoM%   r sag  r trans r long
    {P::kHead,        "head",          "VERT", "MIDG", 203.3,  6.94, 59.76, 36.2, 37.6, 31.2},
    {P::kTrunk,       "trunk",         "SUPR", "MIDH", 531.9, 43.46, 44.86, 37.2, 34.7, 19.1},
    {P::kTrunkMids,   "trunk",         "MIDS", "MIDH", 515.5, 43.46, 43.10, 38.4, 35.8, 19.7},
    {P::kUpperTrunk,  "upper trunk",   "SUPR", "XYPH", 170.7, 15.96, 29.99, 71.6, 45.4, 65.9},
    {P::kMiddleTrunk, "middle trunk",  "XYPH", "OMPH", 215.5, 16.33, 45.02, 48.2, 38.3, 46.8},
    {P::kLowerTrunk,  "lower trunk",   "OMPH", "MIDH", 145.7, 11.17, 61.15, 61.5, 55.1, 58.7},
    {P::kUpperArm,    "upper arm",     "SJC",  "EJC",  281.7,  2.71, 57.72, 28.5, 26.9, 15.8},
    {P::kForearm,     "forearm",       "EJC",  "WJC",  268.9,  1.62, 45.74, 27.6, 26.5, 12.1},
    {P::kHand,        "hand",          "WJC",  "MET3",  86.2,  0.61, 79.00, 62.8, 51.3, 40.1},
    {P::kThigh,       "thigh",         "HJC",  "KJC",  422.2, 14.16, 40.95, 32.9, 32.9, 14.9},
    {P::kShank,       "shank",         "KJC",  "AJC",  440.3,  4.33, 43.95, 25.1, 24.6, 10.2},
    {P::kFoot,        "foot",          "HEEL", "TTIP", 258.1,  1.37, 44.15, 25.7, 24.5, 12.4},
};
const std::vector<DeLevaRow> kFemale = {
    {P::kHead,        "head",          "VERT", "MIDG", 200.2,  6.68, 58.94, 33.0, 35.9, 31.8},
    {P::kTrunk,       "trunk",         "SUPR", "MIDH", 529.3, 42.57, 41.51, 35.7, 33.9, 17.1},
    {P::kTrunkMids,   "trunk",         "MIDS", "MIDH", 497.9, 42.57, 37.82, 37.9, 36.1, 18.2},
    {P::kUpperTrunk,  "upper trunk",   "SUPR", "XYPH", 142.5, 15.45, 20.77, 74.6, 50.2, 71.8},
    {P::kMiddleTrunk, "middle trunk",  "XYPH", "OMPH", 205.3, 14.65, 45.12, 43.3, 35.4, 41.5},
    {P::kLowerTrunk,  "lower trunk",   "OMPH", "MIDH", 181.5, 12.47, 49.20, 43.3, 40.2, 44.4},
    {P::kUpperArm,    "upper arm",     "SJC",  "EJC",  275.1,  2.55, 57.54, 27.8, 26.0, 14.8},
    {P::kForearm,     "forearm",       "EJC",  "WJC",  264.3,  1.38, 45.59, 26.1, 25.7,  9.4},
    {P::kHand,        "hand",          "WJC",  "MET3",  78.0,  0.56, 74.74, 53.1, 45.4, 33.5},
    {P::kThigh,       "thigh",         "HJC",  "KJC",  368.5, 14.78, 36.12, 36.9, 36.4, 16.2},
    {P::kShank,       "shank",         "KJC",  "AJC",  438.6,  4.81, 43.52, 26.7, 26.3,  9.2},
    {P::kFoot,        "foot",          "HEEL", "TTIP", 228.3,  1.29, 40.14, 29.9, 27.9, 13.9},
};
// clang-format on

}  // namespace

std::string sex_name(Sex sex) {
  return sex == Sex::kMale ? "male" : "female";
}

const std::vector<DeLevaRow>& de_leva_rows(Sex sex) {
  return sex == Sex::kMale ? kMale : kFemale;
}

const DeLevaRow& de_leva_row(Sex sex, DeLevaPart part) {
  for (const DeLevaRow& row : de_leva_rows(sex))
    if (row.part == part) return row;
  throw std::logic_error("de_leva_row: a part without a row");
}

double de_leva_stature(Sex sex) {
  return sex == Sex::kMale ? 1.741 : 1.735;
}

}  // namespace saltus
