#include "render/maps.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "math/real.hpp"

namespace promyk {

namespace {

void put(std::uint8_t* out, int j, Rgb8 colour) {
    out[3 * j] = colour.r;
    out[3 * j + 1] = colour.g;
    out[3 * j + 2] = colour.b;
}

// One row's counts per category: written by the thread that computes the
// row, read after render() has joined its threads.
struct RowTally {
    std::vector<int> counts;
    std::vector<int> first_j;
    double largest = -1;
    int largest_j = -1;

    void reset(int categories) {
        counts.assign(static_cast<std::size_t>(categories), 0);
        first_j.assign(static_cast<std::size_t>(categories), -1);
        largest = -1;
        largest_j = -1;
    }
    void add(int category, int j) {
        const auto k = static_cast<std::size_t>(category);
        if (counts[k]++ == 0) first_j[k] = j;
    }
};

// Sums the rows in order, so each category's first pixel is its first in row order.
MapTally sum_rows(const std::vector<RowTally>& rows, std::vector<std::string> names, int first_step = 0,
                  int steps = 0) {
    MapTally tally;
    for (std::string& name : names) tally.categories.push_back({std::move(name), 0, -1, -1});
    for (int k = first_step; k < first_step + steps; ++k)
        tally.categories[static_cast<std::size_t>(k)].listed_if_empty = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const RowTally& row = rows[i];
        if (row.counts.empty()) continue;  // not computed (interrupted)
        for (std::size_t k = 0; k < tally.categories.size(); ++k) {
            MapTally::Category& category = tally.categories[k];
            if (row.counts[k] > 0 && category.count == 0) {
                category.first_i = static_cast<int>(i);
                category.first_j = row.first_j[k];
            }
            category.count += row.counts[k];
        }
        if (row.largest_j >= 0 && (!tally.has_largest || row.largest > tally.largest)) {
            tally.has_largest = true;
            tally.largest = row.largest;
            tally.largest_i = static_cast<int>(i);
            tally.largest_j = row.largest_j;
        }
    }
    return tally;
}

// A map drawn from a kernel's pixels: the traces, intensities and notes are
// the computed kernel's, so --traces beside a map traces what it shows.
class MapOf : public MapKernel {
public:
    MapOf(std::unique_ptr<Kernel> kernel, int w)
        : MapKernel(kernel->stages(), kernel->spp()), kernel_(std::move(kernel)), rows_(static_cast<std::size_t>(w)) {}
    int channels() const override { return 3; }
    Vec3d intensity(int w, int i, int j, Branch* branch) const override { return kernel_->intensity(w, i, j, branch); }
    Vec3<quad> exact_intensity(int w, int i, int j, Branch* branch) const override {
        return kernel_->exact_intensity(w, i, j, branch);
    }
    PixelTrace trace(const TraceHeader& header, int i, int j) const override { return kernel_->trace(header, i, j); }
    PixelNotes notes(int w, int i, int j) const override { return kernel_->notes(w, i, j); }
    double digits_lost(int w, int i, int j, Branch* branch) const override {
        return kernel_->digits_lost(w, i, j, branch);
    }

protected:
    const Kernel& kernel() const { return *kernel_; }
    RowTally& row_tally(int i) const { return rows_[static_cast<std::size_t>(i)]; }
    const std::vector<RowTally>& rows() const { return rows_; }

    static void count_branch(RowCounts& counts, Branch branch, int j) {
        ++counts.branches[static_cast<int>(branch)];
        if (branch == Branch::non_finite && counts.first_non_finite_j < 0) counts.first_non_finite_j = j;
    }

private:
    std::unique_ptr<Kernel> kernel_;
    mutable std::vector<RowTally> rows_;  // one per row, each written by one thread
};

class BranchMap final : public MapOf {
public:
    using MapOf::MapOf;

    RowCounts row(int w, int i, std::uint8_t* out) const override {
        RowCounts counts;
        RowTally& tally = row_tally(i);
        tally.reset(branch_category_count);
        for (int j = 0; j < w; ++j) {
            const PixelNotes notes = kernel().notes(w, i, j);
            count_branch(counts, notes.branch, j);
            const BranchCategory category = branch_category(notes);
            tally.add(static_cast<int>(category), j);
            put(out, j, branch_colour(category).rgb);
        }
        return counts;
    }

    MapTally tally() const override {
        std::vector<std::string> names;
        for (int k = 0; k < branch_category_count; ++k)
            names.emplace_back(branch_colour(static_cast<BranchCategory>(k)).category);
        return sum_rows(rows(), std::move(names));
    }

    double pixel_value(int w, int i, int j) const override {
        return static_cast<double>(branch_category(kernel().notes(w, i, j)));
    }

    std::string description() const override { return ui_message("map_description_branch"); }
    MapKind kind() const override { return MapKind::branch; }
};

// A pixel of a map of one number: the number, or one of the cases that have
// a colour of their own.
struct ScalarPixel {
    enum class Kind { value, zero, branch_differs, non_finite };
    Kind kind = Kind::value;
    Branch branch = Branch::miss;  // the computed pixel's
    double value = 0;              // for Kind::value: finite, > 0
};

// A map of one number a pixel on a ColourScale, with its categories: the
// zero case, one per decade (a log scale) or tenth (a linear one) of the
// scale, below and above it, branch differs and non-finite. The error map is
// one; a digits-lost map would be another, with its own value and scale.
class ScalarMap : public MapOf {
public:
    // `zero` names the value 0's colour; `compares`: whether pixels are
    // compared with a reference (a branch can differ from its branch).
    // Without a scale the map is deferred (MapKernel::deferred): it keeps
    // each pixel until settle() finds the scale from the run's values.
    ScalarMap(std::unique_ptr<Kernel> kernel, int w, std::optional<ColourScale> scale, const LegendColour& zero,
              bool compares)
        : MapOf(std::move(kernel), w), scale_(scale), zero_(zero), compares_(compares), w_(w) {
        // Not zero-filled: at w 4096 writing 128 MB of zeros up front took most of a
        // second in which a signal went unseen; every pixel is written by its row.
        if (!scale_) {
            stored_size_ = static_cast<std::size_t>(w) * static_cast<std::size_t>(w);
            stored_.reset(new double[stored_size_]);
        }
    }

    RowCounts row(int w, int i, std::uint8_t* out) const override {
        RowCounts counts;
        if (!scale_) {  // deferred: record, colour later
            for (int j = 0; j < w; ++j) {
                const ScalarPixel pixel = value(w, i, j);
                count_branch(counts, pixel.branch, j);
                stored_[index(i, j)] = encode(pixel);
                put(out, j, Rgb8{});
            }
            return counts;
        }
        RowTally& tally = row_tally(i);
        tally.reset(category_count());
        for (int j = 0; j < w; ++j) {
            const ScalarPixel pixel = value(w, i, j);
            count_branch(counts, pixel.branch, j);
            colour(pixel, tally, j, out);
        }
        return counts;
    }

    double pixel_value(int w, int i, int j) const override { return encode(value(w, i, j)); }

    bool deferred() const override { return stored_size_ > 0; }
    const ColourScale* colour_scale() const override { return scale_ ? &*scale_ : nullptr; }

    void settle() override { scale_ = scalar_map_scale(kind(), RealType::double_, stored_.get(), stored_size_); }

    void replay_row(int w, int i, std::uint8_t* out) const override {
        RowTally& tally = row_tally(i);
        tally.reset(category_count());
        for (int j = 0; j < w; ++j) colour(decode(stored_[index(i, j)]), tally, j, out);
    }

    MapTally tally() const override {
        if (!scale_) return {};
        std::vector<std::string> names;
        names.emplace_back(zero_.category);
        for (int b = 0; b < bins(); ++b) names.push_back(bin_name(b));
        names.emplace_back(branch_differs_colour().category);
        names.emplace_back(non_finite_error_colour().category);
        MapTally tally = sum_rows(rows(), std::move(names), 1, bins());
        // Without a reference no branch can differ: not listed.
        if (!compares_) tally.categories[static_cast<std::size_t>(category_count() - 2)].listed_if_empty = false;
        return tally;
    }

protected:
    virtual ScalarPixel value(int w, int i, int j) const = 0;

private:
    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(i) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(j);
    }
    // A stored pixel: its value (> 0), 0, or -1 (branch differs), -2 (non-finite).
    static double encode(const ScalarPixel& pixel) {
        switch (pixel.kind) {
            case ScalarPixel::Kind::zero:
                return map_stored_value::zero;
            case ScalarPixel::Kind::branch_differs:
                return map_stored_value::branch_differs;
            case ScalarPixel::Kind::non_finite:
                return map_stored_value::non_finite;
            case ScalarPixel::Kind::value:
                break;
        }
        return pixel.value;
    }
    static ScalarPixel decode(double stored) {
        ScalarPixel pixel;
        pixel.kind = stored > 0                                   ? ScalarPixel::Kind::value
                     : stored == map_stored_value::zero           ? ScalarPixel::Kind::zero
                     : stored == map_stored_value::branch_differs ? ScalarPixel::Kind::branch_differs
                                                                  : ScalarPixel::Kind::non_finite;
        pixel.value = stored;
        return pixel;
    }

    void colour(const ScalarPixel& pixel, RowTally& tally, int j, std::uint8_t* out) const {
        int category;
        switch (pixel.kind) {
            case ScalarPixel::Kind::zero:
                category = 0;
                break;
            case ScalarPixel::Kind::branch_differs:
                category = category_count() - 2;
                break;
            case ScalarPixel::Kind::non_finite:
                category = category_count() - 1;
                break;
            case ScalarPixel::Kind::value:
            default:
                category = 1 + bin(pixel.value);
                if (pixel.value > tally.largest) tally.largest = pixel.value, tally.largest_j = j;
                break;
        }
        tally.add(category, j);
        put(out, j, scalar_map_colour(kind(), *scale_, encode(pixel)));
    }

    // Steps of the scale: decades on a log axis (the last one shorter when
    // the range is not whole decades), tenths on a linear one; plus one
    // below and one at or above its ends.
    int steps() const {
        if (!scale_->logarithmic()) return scale_->linear_steps();
        return std::max(1, static_cast<int>(std::ceil(std::log10(scale_->high() / scale_->low()) - 1e-9)));
    }
    int bins() const { return steps() + 2; }
    int category_count() const { return bins() + 3; }
    double edge(int k) const {  // the lower end of step k
        return scale_->logarithmic()
                   ? std::min(scale_->low() * std::pow(10.0, k), scale_->high())
                   : scale_->low() + (scale_->high() - scale_->low()) * k / steps();
    }
    int bin(double value) const {
        if (value < scale_->low()) return 0;
        if (value >= scale_->high()) return bins() - 1;
        int k = scale_->logarithmic()
                    ? static_cast<int>(std::floor(std::log10(value / scale_->low())))
                    : static_cast<int>(
                          std::floor((value - scale_->low()) / (scale_->high() - scale_->low()) * steps()));
        k = std::clamp(k, 0, steps() - 1);
        // log10 may round across a decade's edge: settle it by comparing.
        if (value < edge(k) && k > 0) --k;
        if (k + 1 < steps() && value >= edge(k + 1)) ++k;
        return 1 + k;
    }
    std::string bin_name(int b) const {
        const auto number = [](double v) { return local_number_text(fmt::format("{:g}", v), ui_language()); };
        if (b == 0) return ui_message("map_bin_below", {{"low", number(scale_->low())}});
        if (b == bins() - 1) return ui_message("map_bin_above", {{"high", number(scale_->high())}});
        return ui_message("map_bin_range", {{"low", number(edge(b - 1))}, {"high", number(edge(b))}});
    }

    std::optional<ColourScale> scale_;
    const LegendColour& zero_;
    bool compares_;
    int w_;
    std::unique_ptr<double[]> stored_;  // deferred: one a pixel, each row written by one thread
    std::size_t stored_size_ = 0;
};

// |I - I_ref|, the largest over r, g, b, against the same pixel in quad with
// the geometric formula at the same samples per pixel. The intensities are
// compared as Kernel::intensity gives them, rounded to double.
class ErrorMap final : public ScalarMap {
public:
    ErrorMap(std::unique_ptr<Kernel> kernel, std::unique_ptr<Kernel> reference, int w,
             std::optional<ColourScale> scale)
        : ScalarMap(std::move(kernel), w, scale, exact_colour(), true), reference_(std::move(reference)) {}

    std::string description() const override { return ui_message("map_description_error"); }
    MapKind kind() const override { return MapKind::error; }

protected:
    ScalarPixel value(int w, int i, int j) const override {
        ScalarPixel pixel;
        Branch reference_branch;
        const Vec3<quad> I = kernel().exact_intensity(w, i, j, &pixel.branch);
        const Vec3<quad> I_ref = reference_->exact_intensity(w, i, j, &reference_branch);
        if (pixel.branch != reference_branch) {
            pixel.kind = ScalarPixel::Kind::branch_differs;
            return pixel;
        }
        // In quad, where both sides are exact: a float's or a long double's
        // error is not blurred by rounding each side to double first.
        quad error = 0;
        bool finite = true;
        for (const quad difference : {I.x - I_ref.x, I.y - I_ref.y, I.z - I_ref.z}) {
            // NaN fails every comparison: a NaN or an infinity on either side is non-finite.
            if (!(quad_math::fabs(difference) <= RealTraits<quad>::max())) finite = false;
            else if (quad_math::fabs(difference) > error) error = quad_math::fabs(difference);
        }
        if (!finite)
            pixel.kind = ScalarPixel::Kind::non_finite;
        else if (error == 0)
            pixel.kind = ScalarPixel::Kind::zero;
        else
            pixel.value = std::max(static_cast<double>(error), std::numeric_limits<double>::denorm_min());
        return pixel;
    }

private:
    std::unique_ptr<Kernel> reference_;
};

// The most digits any traced step of the pixel loses to cancellation
// (Kernel::digits_lost: the trace's largest digits_lost, of any sample).
class DigitsLostMap final : public ScalarMap {
public:
    DigitsLostMap(std::unique_ptr<Kernel> kernel, int w, RealType real)
        : ScalarMap(std::move(kernel), w, digits_lost_scale(real), none_lost_colour(), false) {}

    std::string description() const override { return ui_message("map_description_digits-lost"); }
    MapKind kind() const override { return MapKind::digits_lost; }

protected:
    ScalarPixel value(int w, int i, int j) const override {
        ScalarPixel pixel;
        const double digits = kernel().digits_lost(w, i, j, &pixel.branch);  // one computation: both
        if (pixel.branch == Branch::non_finite)
            pixel.kind = ScalarPixel::Kind::non_finite;
        else if (!(digits > 0))
            pixel.kind = ScalarPixel::Kind::zero;
        else
            pixel.value = digits;
        return pixel;
    }
};

}  // namespace

BranchCategory branch_category(const PixelNotes& notes) {
    if (notes.branch == Branch::non_finite) return BranchCategory::non_finite;
    if (notes.tangent) return BranchCategory::tangent;
    if (notes.behind) return BranchCategory::behind;
    switch (notes.branch) {
        case Branch::dark:
            return BranchCategory::dark;
        case Branch::lit:
            return BranchCategory::lit;
        case Branch::shadowed:
            return BranchCategory::shadowed;
        case Branch::non_finite:
            return BranchCategory::non_finite;
        case Branch::miss:
            break;
    }
    return BranchCategory::miss;
}

Rgb8 scalar_map_colour(MapKind kind, const ColourScale& scale, double stored) {
    if (stored > 0) return scale(stored);
    if (stored == map_stored_value::zero) return kind == MapKind::error ? exact_colour().rgb : none_lost_colour().rgb;
    if (stored == map_stored_value::branch_differs) return branch_differs_colour().rgb;
    return non_finite_error_colour().rgb;
}

ColourScale scalar_map_scale(MapKind kind, RealType real, const double* stored, std::size_t count) {
    if (kind != MapKind::error) return digits_lost_scale(real);
    double smallest = 0, largest = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double v = stored[k];
        if (!(v > 0)) continue;
        if (smallest == 0 || v < smallest) smallest = v;
        largest = std::max(largest, v);
    }
    return smallest > 0 ? error_scale_of_run(smallest, largest) : fallback_error_scale();
}

std::unique_ptr<MapKernel> make_map_kernel(MapKind kind, const Scene& scene, RealType real, Formula formula, int spp,
                                           int w, std::optional<std::pair<double, double>> error_range) {
    std::unique_ptr<Kernel> kernel = make_kernel(scene, real, formula, spp);
    switch (kind) {
        case MapKind::error:
            return std::make_unique<ErrorMap>(
                std::move(kernel), make_kernel(scene, RealType::quad_, Formula::geometric, spp), w,
                error_range ? std::optional<ColourScale>(error_scale(error_range->first, error_range->second))
                            : std::nullopt);
        case MapKind::digits_lost:
            return std::make_unique<DigitsLostMap>(std::move(kernel), w, real);
        case MapKind::branch:
            break;
    }
    return std::make_unique<BranchMap>(std::move(kernel), w);
}

}  // namespace promyk
