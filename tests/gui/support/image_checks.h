#pragma once
// Image checks for the GUI tests: "not blank" and comparison with a committed baseline.
//
// Baselines live in tests/gui/baselines/. A missing baseline writes the candidate image into
// the build tree (SALTUS_GUI_CANDIDATE_DIR) and fails, so that a person looks at it before
// committing it; a mismatch writes the candidate and a difference image there too.
//
// The comparison is deliberately coarse: both images are averaged over 4×4-pixel blocks and a
// block counts as different when a channel differs by more than 40 of 255; at most 3 % of
// blocks may differ. Fonts, anti-aliasing and millimetre changes of a pose (the optimiser and
// the splines are being improved in parallel) stay under that; a missing body, arrow, curve,
// legend or a wrong camera does not.

#include <QColor>
#include <QDir>
#include <QImage>
#include <QString>
#include <set>
#include <string>

namespace saltus::gui::test {

struct BlankCheck {
  int distinct_colours = 0;     ///< among a coarse grid of samples
  double non_background = 0.0;  ///< fraction of pixels unlike the top-left pixel
};

inline BlankCheck blank_check(const QImage& image) {
  BlankCheck out;
  if (image.isNull()) return out;
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  std::set<QRgb> colours;
  const QRgb background = img.pixel(0, 0);
  long different = 0, total = 0;
  for (int y = 0; y < img.height(); y += 2) {
    for (int x = 0; x < img.width(); x += 2) {
      const QRgb p = img.pixel(x, y);
      // Quantised to 32 levels per channel so gradients do not count as many colours.
      colours.insert(qRgb(qRed(p) & 0xF8, qGreen(p) & 0xF8, qBlue(p) & 0xF8));
      ++total;
      different += std::abs(qRed(p) - qRed(background)) + std::abs(qGreen(p) - qGreen(background)) +
                       std::abs(qBlue(p) - qBlue(background)) >
                   30;
    }
  }
  out.distinct_colours = static_cast<int>(colours.size());
  out.non_background = total ? static_cast<double>(different) / total : 0.0;
  return out;
}

/// Fraction of pixels whose colour is close to `colour` (each channel within 40).
inline double colour_fraction(const QImage& image, const QColor& colour) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  long hits = 0, total = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QRgb p = img.pixel(x, y);
      ++total;
      hits += std::abs(qRed(p) - colour.red()) < 40 && std::abs(qGreen(p) - colour.green()) < 40 &&
              std::abs(qBlue(p) - colour.blue()) < 40;
    }
  return total ? static_cast<double>(hits) / total : 0.0;
}

struct Comparison {
  bool ok = false;
  std::string message;
};

inline QImage block_average(const QImage& image, int block) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  QImage out(img.width() / block, img.height() / block, QImage::Format_RGB32);
  for (int by = 0; by < out.height(); ++by)
    for (int bx = 0; bx < out.width(); ++bx) {
      int r = 0, g = 0, b = 0;
      for (int y = 0; y < block; ++y)
        for (int x = 0; x < block; ++x) {
          const QRgb p = img.pixel(bx * block + x, by * block + y);
          r += qRed(p);
          g += qGreen(p);
          b += qBlue(p);
        }
      const int n = block * block;
      out.setPixel(bx, by, qRgb(r / n, g / n, b / n));
    }
  return out;
}

constexpr int kBlock = 4;
constexpr int kChannelTolerance = 40;

/// Share of 4×4 blocks that differ (a channel of the block average by more than 40 of 255)
/// between two images of one size; 1 for different sizes. `diff` (may be null) receives a
/// picture of where they differ (red) and by how much (grey).
inline double block_difference(const QImage& image, const QImage& other, QImage* diff = nullptr) {
  if (image.size() != other.size() || image.isNull()) return 1.0;
  const QImage a = block_average(image, kBlock);
  const QImage b = block_average(other, kBlock);
  if (diff) *diff = QImage(a.size(), QImage::Format_RGB32);
  long different = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      const int d = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q))});
      different += d > kChannelTolerance;
      if (diff)
        diff->setPixel(x, y, d > kChannelTolerance ? qRgb(255, 0, 0) : qRgb(d * 3, d * 3, d * 3));
    }
  return static_cast<double>(different) / (a.width() * a.height());
}

/// Whether two pictures look alike: at most `max_different_blocks` of their blocks differ.
inline bool compare_images(const QImage& image, const QImage& other, double max_different_blocks) {
  return block_difference(image, other) <= max_different_blocks;
}

/// Compares `image` with baselines/<name>.png (see the file comment); at most
/// `max_different_blocks` of the 4×4 blocks may differ.
inline Comparison compare_with_baseline(const QImage& image, const QString& name,
                                        double max_different_blocks = 0.03) {
  const double kMaxDifferentBlocks = max_different_blocks;
  Comparison out;
  const QString baseline_path = QDir(SALTUS_GUI_BASELINE_DIR).filePath(name + ".png");
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  const QString candidate_path = QDir(SALTUS_GUI_CANDIDATE_DIR).filePath(name + ".png");
  const QImage baseline(baseline_path);
  if (baseline.isNull()) {
    image.save(candidate_path, "PNG");
    out.message = ("no baseline " + baseline_path + "; wrote the candidate " + candidate_path +
                   " - look at it, then copy it there to accept it")
                      .toStdString();
    return out;
  }
  if (baseline.size() != image.size()) {
    image.save(candidate_path, "PNG");
    out.message = QString("size %1x%2 differs from the baseline's %3x%4; candidate in %5")
                      .arg(image.width())
                      .arg(image.height())
                      .arg(baseline.width())
                      .arg(baseline.height())
                      .arg(candidate_path)
                      .toStdString();
    return out;
  }
  QImage diff;
  const double fraction = block_difference(image, baseline, &diff);
  out.ok = fraction <= kMaxDifferentBlocks;
  if (!out.ok) {
    image.save(candidate_path, "PNG");
    const QString diff_path = QDir(SALTUS_GUI_CANDIDATE_DIR).filePath(name + "-diff.png");
    diff.save(diff_path, "PNG");
    out.message = QString(
                      "%1 % of 4x4 blocks differ from %2 (at most %3 % allowed); candidate %4, "
                      "difference %5")
                      .arg(100 * fraction, 0, 'f', 2)
                      .arg(baseline_path)
                      .arg(100 * kMaxDifferentBlocks, 0, 'f', 1)
                      .arg(candidate_path, diff_path)
                      .toStdString();
  }
  return out;
}

}  // namespace saltus::gui::test
