// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NumPy arrays from the core's vectors (copies: the arrays own their data).

#include <pybind11/numpy.h>

#include <cstddef>
#include <vector>

namespace kinstab::python {

template <typename T> pybind11::array_t<T> toArray(const std::vector<T>& v) {
    pybind11::array_t<T> a(static_cast<pybind11::ssize_t>(v.size()));
    T* out = a.mutable_data();
    for (std::size_t i = 0; i < v.size(); ++i)
        out[i] = v[i];
    return a;
}

// One field of each element: column(events, [](const SlabEvent& e) { return e.tau; }).
template <typename T, typename S, typename F>
pybind11::array_t<T> column(const std::vector<S>& rows, F field) {
    pybind11::array_t<T> a(static_cast<pybind11::ssize_t>(rows.size()));
    T* out = a.mutable_data();
    for (std::size_t i = 0; i < rows.size(); ++i)
        out[i] = static_cast<T>(field(rows[i]));
    return a;
}

} // namespace kinstab::python
