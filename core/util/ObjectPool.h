#pragma once
// Objects that are costly to make (a face detector with its models, a speech decoder) shared by
// the jobs of parallel work: each job takes an idle one, or a new one, and gives it back when
// done, so no more are made than jobs run at once. Thread-safe.
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace lipsync {

template<class T>
class ObjectPool
{
public:
    explicit ObjectPool(std::function<std::unique_ptr<T>()> make) : m_make(std::move(make)) {}

    // An idle object, or a new one (the maker's exceptions pass through).
    std::unique_ptr<T> take()
    {
        {
            const std::lock_guard lock(m_mutex);
            if (!m_idle.empty()) {
                std::unique_ptr<T> object = std::move(m_idle.back());
                m_idle.pop_back();
                return object;
            }
        }
        return m_make();
    }
    void give(std::unique_ptr<T> object)
    {
        if (!object)
            return;
        const std::lock_guard lock(m_mutex);
        m_idle.push_back(std::move(object));
    }

    // An object taken for one scope and given back at its end.
    class Lease
    {
    public:
        explicit Lease(ObjectPool &pool) : m_pool(pool), m_object(pool.take()) {}
        ~Lease() { m_pool.give(std::move(m_object)); }
        Lease(const Lease &) = delete;
        Lease &operator=(const Lease &) = delete;
        T &operator*() const { return *m_object; }
        T *operator->() const { return m_object.get(); }

    private:
        ObjectPool &m_pool;
        std::unique_ptr<T> m_object;
    };

private:
    std::function<std::unique_ptr<T>()> m_make;
    std::mutex m_mutex;
    std::vector<std::unique_ptr<T>> m_idle;
};

} // namespace lipsync
