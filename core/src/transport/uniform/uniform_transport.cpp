#include "rad/transport/uniform/uniform_transport.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "rad/mesh/patch_albedo.hpp"

namespace rad {

void UniformTransport::gather(std::span<const glm::dvec3> radiosity, std::span<glm::dvec3> irradiance) const {
    // Rows in parallel, each row's sum in column order: the result does not depend on the thread count.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& rows) {
                          for (std::size_t i = rows.begin(); i != rows.end(); ++i) {
                              const FormFactorRow row = form_factors.row(i);
                              glm::dvec3 sum(0.0);
                              for (std::size_t k = 0; k < row.size(); ++k)
                                  sum += static_cast<double>(row.values[k]) * radiosity[row.columns[k]];
                              irradiance[i] = sum;
                          }
                      });
}

std::vector<double> UniformTransport::reach() const {
    std::vector<double> sums(size());
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i] = form_factors.row(i).sum();
    return sums;
}

std::vector<double> UniformTransport::escape() const {
    if (form_factors.escaped.size() != size()) return Transport::escape();
    return std::vector<double>(form_factors.escaped.begin(), form_factors.escaped.end());
}

TransportReport UniformTransport::report() const {
    const FormFactorReport& ff = form_factor_report;
    TransportReport r;
    r.kind = kind;
    r.interaction_name = "form factors";
    r.elements = size();
    r.interactions = form_factors.nonzeros();
    r.memory_bytes = form_factors.memory_bytes();
    r.rays = ff.rays;
    r.seconds = ff.seconds;
    r.form_factor_passes = form_factor_passes;
    // The pass measured the row sums; the viewer asks for a report after every step.
    r.details = {{"min_row_sum", ff.min_row_sum},
                 {"max_row_sum", ff.max_row_sum},
                 {"rows_over_one", static_cast<double>(ff.rows_over_one)},
                 {"escaped_ray_fraction", ff.escaped_ray_fraction},
                 {"covered_area_fraction", ff.covered_area_fraction},
                 {"max_reciprocity_error", ff.max_reciprocity_error},
                 {"mean_reciprocity_error", ff.mean_reciprocity_error}};
    r.details.insert(r.details.end(), details.begin(), details.end());
    r.notes = notes;
    if (ff.rows_over_one > 0) {
        char line[200];
        std::snprintf(
            line, sizeof line,
            "%zu row(s) of form factors sum over %.2f (largest %.4f): their estimate counts some light "
            "twice; normalizing the rows (closed scenes) scales them to 1",
            ff.rows_over_one, 1.0 + kRowSumSlack, ff.max_row_sum);
        r.notes += (r.notes.empty() ? "" : "; ") + std::string(line);
    }
    return r;
}

UniformTransport make_uniform_transport(const Scene& scene, const PatchMesh& patches,
                                        FormFactorMatrix form_factors, const FormFactorReport& report) {
    UniformTransport transport;
    const std::size_t n = patches.size();
    transport.area.reserve(n);
    transport.reflectance.reserve(n);
    transport.emission.reserve(n);
    transport.reflectance = patch_albedo(scene, patches);
    for (std::size_t i = 0; i < n; ++i) {
        const Patch& patch = patches.patches[i];
        const Material& material = scene.surfaces.at(patch.surface).material;
        // Only the exposed part of a patch emits, absorbs and reflects into the scene.
        transport.area.push_back(patch.area * form_factors.exposed_fraction(i));
        transport.emission.push_back(material.emitted_radiosity());
    }
    transport.form_factors = std::move(form_factors);
    transport.form_factor_report = report;
    validate_uniform_transport(transport);
    return transport;
}

std::vector<glm::dvec3> whole_patch_radiosity(const Transport& transport, const PatchMesh& patches,
                                              std::span<const glm::dvec3> radiosity) {
    std::vector<glm::dvec3> whole(radiosity.begin(), radiosity.end());
    for (std::size_t i = 0; i < whole.size(); ++i) whole[i] *= transport.area[i] / patches.patches[i].area;
    return whole;
}

void validate_form_factor_matrix(const FormFactorMatrix& f, std::size_t n) {
    if (f.rows() != n || f.row_begin.front() != 0 || f.row_begin.back() != f.nonzeros() ||
        f.value.size() != f.nonzeros()) {
        throw std::invalid_argument("radiosity system: the form-factor matrix does not match the patches");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (f.row_begin[i] > f.row_begin[i + 1]) {
            throw std::invalid_argument("radiosity system: form-factor row " + std::to_string(i) +
                                        " is malformed");
        }
    }
    for (std::size_t k = 0; k < f.nonzeros(); ++k) {
        const float v = f.value[k];
        if (f.column[k] >= n || !std::isfinite(v) || v < 0.0f) {
            throw std::invalid_argument("radiosity system: form-factor entry " + std::to_string(k) +
                                        " has a bad column or value");
        }
    }
}

void validate_uniform_transport(const UniformTransport& transport) {
    validate_elements(transport);
    validate_form_factor_matrix(transport.form_factors, transport.size());
}

}  // namespace rad
