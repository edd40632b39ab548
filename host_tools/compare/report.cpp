#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/compare.hpp"
#include "io/number_text.hpp"

namespace spanlight::compare {

using io::number_text;

std::string psnr_text(double psnr_db) { return std::isinf(psnr_db) ? "inf" : number_text("%.2f", psnr_db); }

std::string to_json(const CompareResult& r) {
  nlohmann::ordered_json json;
  json["width"] = r.width;
  json["height"] = r.height;
  // JSON has no infinity: identical images give null.
  json["psnr_db"] = std::isinf(r.psnr_db) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.psnr_db);
  json["max_abs_lsb"] = r.max_abs_lsb;
  json["mean_abs_lsb"] = r.mean_abs_lsb;
  json["pct_over_2_lsb"] = r.pct_over_2_lsb;
  json["pct_over_8_lsb"] = r.pct_over_8_lsb;
  return json.dump(2);
}

std::string to_text(const CompareResult& r) {
  return "size            " + std::to_string(r.width) + " x " + std::to_string(r.height) + "\n" +
         "PSNR            " + psnr_text(r.psnr_db) + " dB\n" +
         "max |diff|      " + number_text("%g", r.max_abs_lsb) + " LSB\n" +
         "mean |diff|     " + number_text("%.3f", r.mean_abs_lsb) + " LSB\n" +
         "pixels > 2 LSB  " + number_text("%.2f", r.pct_over_2_lsb) + " %\n" +
         "pixels > 8 LSB  " + number_text("%.2f", r.pct_over_8_lsb) + " %\n";
}

std::string to_one_line(const CompareResult& r) {
  return std::to_string(r.width) + "x" + std::to_string(r.height) + "  PSNR " + psnr_text(r.psnr_db) + " dB  max " +
         number_text("%g", r.max_abs_lsb) + " LSB  mean " + number_text("%.3f", r.mean_abs_lsb) + " LSB  >2 LSB " +
         number_text("%.2f", r.pct_over_2_lsb) + "%  >8 LSB " + number_text("%.2f", r.pct_over_8_lsb) + "%";
}

}  // namespace spanlight::compare
