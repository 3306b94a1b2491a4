#pragma once

#include <utility>

namespace caliper3d::scenegraph {

// Holds one reference on a Coin node (ref() on take, unref() on release), so
// ownership is a value instead of scattered ref()/unref() pairs.
template <typename Node>
class NodeRef {
public:
    NodeRef() = default;
    explicit NodeRef(Node* node) : m_node(node) {
        if (m_node) m_node->ref();
    }
    NodeRef(const NodeRef& other) : NodeRef(other.m_node) {}
    NodeRef(NodeRef&& other) noexcept : m_node(std::exchange(other.m_node, nullptr)) {}
    NodeRef& operator=(NodeRef other) noexcept {
        std::swap(m_node, other.m_node);
        return *this;
    }
    ~NodeRef() {
        if (m_node) m_node->unref();
    }

    Node* get() const { return m_node; }
    Node* operator->() const { return m_node; }
    explicit operator bool() const { return m_node != nullptr; }

private:
    Node* m_node = nullptr;
};

template <typename Node>
NodeRef<Node> makeRef(Node* node) {
    return NodeRef<Node>(node);
}

}  // namespace caliper3d::scenegraph
