#include "rad/radiosity_system.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rad {

namespace {

bool finite_non_negative(double v) {
    return std::isfinite(v) && v >= 0.0;
}
bool finite_non_negative(const glm::dvec3& v) {
    return finite_non_negative(v.x) && finite_non_negative(v.y) && finite_non_negative(v.z);
}

void check_patch_values(const RadiositySystem& system) {
    const std::size_t n = system.size();
    if (n == 0) throw std::invalid_argument("radiosity system: no patches");
    if (system.reflectance.size() != n || system.emission.size() != n) {
        throw std::invalid_argument("radiosity system: area, reflectance and emission differ in size");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!finite_non_negative(system.area[i]) || system.area[i] == 0.0) {
            throw std::invalid_argument("radiosity system: patch " + std::to_string(i) +
                                        " has no finite area");
        }
        if (!finite_non_negative(system.reflectance[i]) || !finite_non_negative(system.emission[i])) {
            throw std::invalid_argument("radiosity system: patch " + std::to_string(i) +
                                        " has a negative or non-finite reflectance or emission");
        }
    }
}

void check_form_factors(const FormFactorMatrix& f, std::size_t n) {
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
        if (f.column[k] >= n || !finite_non_negative(static_cast<double>(f.value[k]))) {
            throw std::invalid_argument("radiosity system: form-factor entry " + std::to_string(k) +
                                        " has a bad column or value");
        }
    }
}

}  // namespace

RadiositySystem make_radiosity_system(const Scene& scene, const PatchMesh& patches,
                                      FormFactorMatrix form_factors) {
    RadiositySystem system;
    const std::size_t n = patches.size();
    system.area.reserve(n);
    system.reflectance.reserve(n);
    system.emission.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Patch& patch = patches.patches[i];
        const Material& material = scene.surfaces.at(patch.surface).material;
        // Only the exposed part of a patch emits, absorbs and reflects into the scene.
        system.area.push_back(patch.area * form_factors.exposed_fraction(i));
        system.reflectance.push_back(material.reflectance);
        system.emission.push_back(material.emitted_radiosity());
    }
    system.form_factors = std::move(form_factors);
    validate_radiosity_system(system);
    return system;
}

std::vector<glm::dvec3> whole_patch_radiosity(const RadiositySystem& system, const PatchMesh& patches,
                                              std::span<const glm::dvec3> radiosity) {
    std::vector<glm::dvec3> whole(radiosity.begin(), radiosity.end());
    for (std::size_t i = 0; i < whole.size(); ++i) whole[i] *= system.area[i] / patches.patches[i].area;
    return whole;
}

void validate_radiosity_system(const RadiositySystem& system) {
    check_patch_values(system);
    check_form_factors(system.form_factors, system.size());
}

EnergyBalance energy_balance(const RadiositySystem& system, std::span<const glm::dvec3> radiosity) {
    if (radiosity.size() != system.size()) {
        throw std::invalid_argument("energy_balance: the radiosity has the wrong number of patches");
    }
    const FormFactorMatrix& f = system.form_factors;
    EnergyBalance balance;
    for (std::size_t i = 0; i < system.size(); ++i) {
        glm::dvec3 arriving(0.0);
        double row_sum = 0.0;
        for (std::uint64_t k = f.row_begin[i]; k < f.row_begin[i + 1]; ++k) {
            arriving += static_cast<double>(f.value[k]) * radiosity[f.column[k]];
            row_sum += static_cast<double>(f.value[k]);
        }
        const double a = system.area[i];
        balance.emitted += a * system.emission[i];
        balance.absorbed += a * (1.0 - system.reflectance[i]) * arriving;
        balance.escaped += a * (1.0 - row_sum) * radiosity[i];
    }
    return balance;
}

}  // namespace rad
