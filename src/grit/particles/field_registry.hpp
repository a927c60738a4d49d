// The registry of per-particle fields: named structure-of-arrays columns that are sorted, compacted,
// grown, backed up, written to snapshots and saved to checkpoints together, so no model keeps private
// per-particle arrays.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "grit/core/sym_tensor.hpp"
#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/io/point_data.hpp"

namespace grit::particles {

/// Type-erased column; the registry moves particles through this interface only.
class FieldBase {
public:
    FieldBase(std::string name, bool output, bool saved) : name_(std::move(name)), output_(output), saved_(saved) {}
    virtual ~FieldBase() = default;
    FieldBase(const FieldBase&) = default;
    FieldBase& operator=(const FieldBase&) = default;

    const std::string& name() const { return name_; }
    bool is_output() const { return output_; }
    /// Saved in checkpoints: every field a later step reads. Scratch recomputed before it is read
    /// within the same step may opt out.
    bool is_saved() const { return saved_; }

    virtual void resize(Index n) = 0;
    /// new[i] = old[source[i]]; reorders and removes in one pass.
    virtual void gather(const std::vector<Index>& source) = 0;
    virtual std::unique_ptr<FieldBase> clone() const = 0;
    /// Entry `to` becomes the mirror image of entry `from` in the plane normal to `axis` through the
    /// origin (a symmetry plane): vectors change the sign of their `axis` component, symmetric tensors
    /// of their off-diagonal components in that row; scalars are copied.
    virtual void mirror_copy(Index from, Index to, int axis) = 0;
    /// The same for each pair (from[k], to[k]).
    virtual void mirror_copy(const std::vector<Index>& from, const std::vector<Index>& to, int axis) = 0;
    /// Entry to[k] becomes a copy of entry from[k], for each k (a periodic ghost of its owner).
    virtual void copy(const std::vector<Index>& from, const std::vector<Index>& to) = 0;
    /// The bytes one entry packs to.
    virtual std::size_t entry_bytes() const = 0;
    /// Appends the entries `rows`, in that order, to `out` as raw bytes (a message to another sub-domain).
    virtual void pack(const std::vector<Index>& rows, std::vector<std::byte>& out) const = 0;
    /// Entry rows[k] becomes the k-th entry packed at `in` (by the same field of another sub-domain);
    /// returns the bytes read.
    virtual std::size_t unpack(const std::byte* in, const std::vector<Index>& rows) = 0;
    /// Appends this column, as written to snapshots, to `cloud` (vectors padded to 3 components).
    /// `phase` and `material` (the particles' phases and material indices, or null) apply the output
    /// scope: a real-valued column is written as NaN on the particles it means nothing for.
    virtual void append_output(io::PointCloud& cloud, const std::int32_t* phase = nullptr,
                               const std::int32_t* material = nullptr) const = 0;

    /// Where the column means something, as a function of a particle's phase and material index.
    using Scope = std::function<bool(std::int32_t phase, std::int32_t material)>;
    /// Limits the column in snapshots to the particles `defined` accepts (unset: every particle). ParaView
    /// leaves NaN out of colour ranges, so a solid-only field no longer shows the water as 0 K or 0 strain.
    void set_output_scope(Scope defined) { scope_ = std::move(defined); }
    bool defined_for(std::int32_t phase, std::int32_t material) const { return !scope_ || scope_(phase, material); }
    /// Writes the column as a dataset named after the field (rows = particles, one column per scalar
    /// component), bit for bit.
    virtual void save(io::Hdf5Group& group) const = 0;
    /// Reads the column back; the dataset must have `size` rows and this type's components.
    virtual void load(const io::Hdf5Group& group, Index size) = 0;
    /// The column's bytes (for bit-for-bit comparisons in tests).
    virtual std::vector<unsigned char> bytes() const = 0;

private:
    std::string name_;
    bool output_;
    bool saved_;
    Scope scope_;
};

template <class T>
class Field final : public FieldBase {
public:
    Field(std::string name, T fill, bool output, bool saved = true)
        : FieldBase(std::move(name), output, saved), fill_(fill) {}

    T* data() noexcept { return values_.data(); }
    const T* data() const noexcept { return values_.data(); }
    T& operator[](Index i) noexcept { return values_[static_cast<std::size_t>(i)]; }
    const T& operator[](Index i) const noexcept { return values_[static_cast<std::size_t>(i)]; }
    Index size() const noexcept { return static_cast<Index>(values_.size()); }
    const T& fill_value() const noexcept { return fill_; }

    void resize(Index n) override { values_.resize(static_cast<std::size_t>(n), fill_); }
    void gather(const std::vector<Index>& source) override {
        std::vector<T> next(source.size());
        for (std::size_t i = 0; i < source.size(); ++i) next[i] = values_[static_cast<std::size_t>(source[i])];
        values_.swap(next);
    }
    std::unique_ptr<FieldBase> clone() const override { return std::make_unique<Field<T>>(*this); }
    void mirror_copy(Index from, Index to, int axis) override {
        values_[static_cast<std::size_t>(to)] = mirrored(values_[static_cast<std::size_t>(from)], axis);
    }
    void mirror_copy(const std::vector<Index>& from, const std::vector<Index>& to, int axis) override {
        for (std::size_t k = 0; k < from.size(); ++k)
            values_[static_cast<std::size_t>(to[k])] = mirrored(values_[static_cast<std::size_t>(from[k])], axis);
    }
    void copy(const std::vector<Index>& from, const std::vector<Index>& to) override {
        for (std::size_t k = 0; k < from.size(); ++k)
            values_[static_cast<std::size_t>(to[k])] = values_[static_cast<std::size_t>(from[k])];
    }
    std::size_t entry_bytes() const override { return sizeof(T); }
    void pack(const std::vector<Index>& rows, std::vector<std::byte>& out) const override {
        const std::size_t start = out.size();
        out.resize(start + rows.size() * sizeof(T));
        for (std::size_t k = 0; k < rows.size(); ++k)
            std::memcpy(out.data() + start + k * sizeof(T), &values_[static_cast<std::size_t>(rows[k])], sizeof(T));
    }
    std::size_t unpack(const std::byte* in, const std::vector<Index>& rows) override {
        for (std::size_t k = 0; k < rows.size(); ++k)
            std::memcpy(&values_[static_cast<std::size_t>(rows[k])], in + k * sizeof(T), sizeof(T));
        return rows.size() * sizeof(T);
    }
    void append_output(io::PointCloud& cloud, const std::int32_t* phase = nullptr,
                       const std::int32_t* material = nullptr) const override;
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group, Index size) override;
    std::vector<unsigned char> bytes() const override {
        const auto* p = reinterpret_cast<const unsigned char*>(values_.data());
        return {p, p + values_.size() * sizeof(T)};
    }

private:
    // Every field type is an int32, an int64 (ids) or an array of doubles (Vec, SymTensor3, Spin): its
    // scalar type and the number of scalars per particle.
    static T mirrored(T value, int axis) {
        if constexpr (std::is_same_v<T, core::Vec<2>> || std::is_same_v<T, core::Vec<3>>) {
            value[axis] = -value[axis];
        } else if constexpr (std::is_same_v<T, core::SymTensor3>) {
            // xy couples axes 0 and 1, yz axes 1 and 2, zx axes 2 and 0.
            if (axis != 2) value.xy = -value.xy;
            if (axis != 0) value.yz = -value.yz;
            if (axis != 1) value.zx = -value.zx;
        }
        return value;
    }
    using Scalar = std::conditional_t<std::is_integral_v<T>, T, double>;
    static constexpr std::size_t components = sizeof(T) / sizeof(Scalar);
    static_assert(sizeof(T) % sizeof(Scalar) == 0 && std::is_trivially_copyable_v<T>);

    std::vector<T> values_;
    T fill_;
};

template <class T>
void Field<T>::append_output(io::PointCloud& cloud, const std::int32_t* phase, const std::int32_t* material) const {
    io::PointArray a;
    a.name = name();
    if constexpr (std::is_same_v<T, double>) {
        a.real = values_;
    } else if constexpr (std::is_same_v<T, std::int32_t>) {
        a.is_integer = true;
        a.integer = values_;
    } else if constexpr (std::is_same_v<T, std::int64_t>) {
        a.is_integer = true;
        a.is_int64 = true;
        a.integer64 = values_;
    } else if constexpr (std::is_same_v<T, core::Vec<2>> || std::is_same_v<T, core::Vec<3>>) {
        constexpr int dim = std::is_same_v<T, core::Vec<2>> ? 2 : 3;
        a.components = 3;
        a.real.assign(values_.size() * 3, 0.0);
        for (std::size_t i = 0; i < values_.size(); ++i)
            for (int k = 0; k < dim; ++k) a.real[3 * i + static_cast<std::size_t>(k)] = values_[i][k];
    } else if constexpr (std::is_same_v<T, core::SymTensor3>) {
        // ParaView's symmetric-tensor order: XX, YY, ZZ, XY, YZ, XZ.
        a.components = 6;
        a.real.reserve(values_.size() * 6);
        for (const auto& t : values_) a.real.insert(a.real.end(), {t.xx, t.yy, t.zz, t.xy, t.yz, t.zx});
    } else {
        static_assert(sizeof(T) == 0, "field type has no output form");
    }
    if (phase != nullptr && material != nullptr && !a.is_integer) {
        const auto c = static_cast<std::size_t>(a.components);
        for (std::size_t i = 0; i < values_.size(); ++i)
            if (!defined_for(phase[i], material[i]))
                std::fill_n(a.real.begin() + static_cast<std::ptrdiff_t>(c * i), c,
                            std::numeric_limits<double>::quiet_NaN());
    }
    cloud.arrays.push_back(std::move(a));
}

template <class T>
void Field<T>::save(io::Hdf5Group& group) const {
    group.write(name(), reinterpret_cast<const Scalar*>(values_.data()), values_.size(), components);
}

template <class T>
void Field<T>::load(const io::Hdf5Group& group, Index size) {
    std::size_t rows = 0;
    std::vector<Scalar> raw;
    if constexpr (std::is_same_v<Scalar, double>) raw = group.read_doubles(name(), components, rows);
    else if constexpr (std::is_same_v<Scalar, std::int64_t>) raw = group.read_int64(name(), components, rows);
    else raw = group.read_int32(name(), components, rows);
    if (rows != static_cast<std::size_t>(size))
        throw io::Hdf5Error(group.path() + "/" + name() + ": " + std::to_string(rows) + " rows, expected " +
                            std::to_string(size));
    values_.resize(rows);
    if (!raw.empty()) std::memcpy(static_cast<void*>(values_.data()), raw.data(), raw.size() * sizeof(Scalar));
}

/// All fields of one particle set. Fields are created by the models that need them.
class FieldRegistry {
public:
    FieldRegistry() = default;
    FieldRegistry(const FieldRegistry& other) : size_(other.size_) {
        for (const auto& f : other.fields_) fields_.push_back(f->clone());
        for (std::size_t k = 0; k < fields_.size(); ++k) index_[fields_[k]->name()] = k;
    }
    FieldRegistry& operator=(const FieldRegistry& other) {
        if (this != &other) {
            FieldRegistry copy(other);
            fields_.swap(copy.fields_);
            index_.swap(copy.index_);
            size_ = copy.size_;
        }
        return *this;
    }
    FieldRegistry(FieldRegistry&&) = default;
    FieldRegistry& operator=(FieldRegistry&&) = default;

    /// Adds a field (or returns the existing one of the same name and type).
    /// `output`: written to snapshots; `saved`: written to checkpoints (see FieldBase::is_saved).
    template <class T>
    Field<T>& add(const std::string& name, T fill, bool output, bool saved = true) {
        if (auto it = index_.find(name); it != index_.end()) {
            auto* f = dynamic_cast<Field<T>*>(fields_[it->second].get());
            if (!f) throw std::logic_error("field '" + name + "' already registered with another type");
            return *f;
        }
        auto field = std::make_unique<Field<T>>(name, fill, output, saved);
        field->resize(size_);
        auto& ref = *field;
        index_[name] = fields_.size();
        fields_.push_back(std::move(field));
        return ref;
    }

    /// The field of that name, whatever its type.
    FieldBase& base(const std::string& name) {
        auto it = index_.find(name);
        if (it == index_.end()) throw std::logic_error("no field '" + name + "'");
        return *fields_[it->second];
    }

    template <class T>
    Field<T>& get(const std::string& name) {
        auto it = index_.find(name);
        if (it == index_.end()) throw std::logic_error("no field '" + name + "'");
        auto* f = dynamic_cast<Field<T>*>(fields_[it->second].get());
        if (!f) throw std::logic_error("field '" + name + "' has another type");
        return *f;
    }

    template <class T>
    const Field<T>& get(const std::string& name) const {
        return const_cast<FieldRegistry*>(this)->get<T>(name);
    }

    bool has(const std::string& name) const { return index_.count(name) != 0; }
    /// Every field, in registration order.
    std::vector<const FieldBase*> all() const {
        std::vector<const FieldBase*> out;
        for (const auto& f : fields_) out.push_back(f.get());
        return out;
    }
    Index size() const noexcept { return size_; }

    void resize(Index n) {
        for (auto& f : fields_) f->resize(n);
        size_ = n;
    }
    /// Entry `to` of every field becomes the mirror image of entry `from` (FieldBase::mirror_copy).
    void mirror_copy(Index from, Index to, int axis) {
        for (auto& f : fields_) f->mirror_copy(from, to, axis);
    }
    void mirror_copy(const std::vector<Index>& from, const std::vector<Index>& to, int axis) {
        for (auto& f : fields_) f->mirror_copy(from, to, axis);
    }
    /// Entry to[k] of every field becomes a copy of entry from[k] (FieldBase::copy).
    void copy(const std::vector<Index>& from, const std::vector<Index>& to) {
        for (auto& f : fields_) f->copy(from, to);
    }
    /// Every field's entries `rows`, field after field in registration order (a registry with the same
    /// fields registered in the same order, another sub-domain's, unpacks them).
    std::vector<std::byte> pack(const std::vector<Index>& rows) const {
        std::vector<std::byte> out;
        for (const auto& f : fields_) f->pack(rows, out);
        return out;
    }
    /// The bytes one particle packs to.
    std::size_t entry_bytes() const {
        std::size_t entry = 0;
        for (const auto& f : fields_) entry += f->entry_bytes();
        return entry;
    }
    /// Entries `rows` become those packed in `in`; `in` must hold exactly as many.
    void unpack(const std::vector<std::byte>& in, const std::vector<Index>& rows) {
        const std::size_t entry = entry_bytes();
        if (in.size() != rows.size() * entry)
            throw std::logic_error("particle message of " + std::to_string(in.size()) + " bytes for " +
                                   std::to_string(rows.size()) + " particles of " + std::to_string(entry) + " bytes");
        std::size_t read = 0;
        for (auto& f : fields_) read += f->unpack(in.data() + read, rows);
    }
    void gather(const std::vector<Index>& source) {
        for (auto& f : fields_) f->gather(source);
        size_ = static_cast<Index>(source.size());
    }
    /// Every output field into `cloud`; `phase` and `material` as in FieldBase::append_output.
    void append_output(io::PointCloud& cloud, const std::int32_t* phase = nullptr,
                       const std::int32_t* material = nullptr) const {
        for (const auto& f : fields_)
            if (f->is_output()) f->append_output(cloud, phase, material);
    }
    /// Every saved field as a dataset of `group`, and the particle count as its attribute `size`.
    void save(io::Hdf5Group& group) const {
        group.write("size", static_cast<std::int64_t>(size_));
        for (const auto& f : fields_)
            if (f->is_saved()) f->save(group);
    }
    /// Reads every saved field back (each must be in `group`); unsaved fields take their fill value.
    void load(const io::Hdf5Group& group) {
        const auto n = static_cast<Index>(group.read_int("size"));
        resize(0);
        resize(n);
        for (auto& f : fields_)
            if (f->is_saved()) f->load(group, n);
    }

private:
    std::vector<std::unique_ptr<FieldBase>> fields_;
    std::map<std::string, std::size_t, std::less<>> index_;
    Index size_ = 0;
};

}  // namespace grit::particles
