#include "print_flags.hpp"

#include <fmt/format.h>

#include "dragon/errors.hpp"

namespace dragon::cli {

void PrintFlags::add_to(CLI::App* sub) {
    sub->add_option("--print", preset_,
                    "Print size for a paper: column (3.5 in wide, text 8 pt), page (7 in, 9 pt) or a4 (16 cm, "
                    "10.5 pt); PNG at 300 dpi. --width-in/--width-cm, --font-pt and --dpi adjust it");
    auto* in = sub->add_option("--width-in", width_in_, "Width on the page in inches (1..40; a print size)");
    auto* cm = sub->add_option("--width-cm", width_cm_, "Width on the page in centimetres (2.54..101.6; a print size)");
    in->excludes(cm);
    sub->add_option("--font-pt", font_pt_, "Text size in points at that width (4..36; titles a fifth larger; default 8)");
    sub->add_option("--dpi", dpi_, "PNG pixels per inch at a print size (72..1200, default 300; stated in the file)");
}

bool PrintFlags::given() const { return preset_ || width_in_ || width_cm_ || font_pt_ || dpi_; }

std::optional<PrintSize> PrintFlags::resolve() const {
    if (!given()) return std::nullopt;
    PrintSize size = preset_ ? print_preset(*preset_) : PrintSize{};
    if (width_cm_ && !(*width_cm_ >= kMinPrintWidthIn * kCmPerInch && *width_cm_ <= kMaxPrintWidthIn * kCmPerInch))
        throw InputError(fmt::format("--width-cm {} is not allowed: give centimetres, {:g}..{:g}", error_value(*width_cm_),
                                     kMinPrintWidthIn * kCmPerInch, kMaxPrintWidthIn * kCmPerInch));
    if (width_in_) size.width_in = *width_in_;
    if (width_cm_) size.width_in = *width_cm_ / kCmPerInch;
    if (font_pt_) size.font_pt = *font_pt_;
    if (dpi_) size.dpi = *dpi_;
    check_print_size(size);
    return size;
}

}  // namespace dragon::cli
