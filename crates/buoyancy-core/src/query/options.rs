//! How one query is computed: [`Query`], the method, the traversal and the threads.

use crate::query::{Method, Traversal};

/// How [`Mesh::buoyancy`](crate::Mesh::buoyancy) computes: the [`Method`], the [`Traversal`]
/// and (feature `rayon`) whether the work is split across rayon's thread pool. A [`Method`]
/// alone is a `Query` with the [`Auto`](Traversal::Auto) traversal on the calling thread.
///
/// Every traversal, and the serial and parallel runs, give the same result (the parallel one
/// bit-identical to the serial): they change the cost only.
///
/// ```
/// use buoyancy_core::query::Query;
/// use buoyancy_core::{Method, Traversal};
///
/// let query = Query::new(Method::Exact).with_traversal(Traversal::Scan);
/// assert_eq!((query.method(), query.traversal()), (Method::Exact, Traversal::Scan));
/// assert_eq!(Query::from(Method::Fast), Query::new(Method::Fast));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Query {
    method: Method,
    traversal: Traversal,
    parallel: bool,
}

impl Query {
    /// `method` on the [`Auto`](Traversal::Auto) traversal, on the calling thread.
    pub const fn new(method: Method) -> Self {
        Query {
            method,
            traversal: Traversal::Auto,
            parallel: false,
        }
    }

    /// This query on `traversal`.
    pub const fn with_traversal(mut self, traversal: Traversal) -> Self {
        self.traversal = traversal;
        self
    }

    /// This query with its work split across rayon's thread pool: the triangles in chunks
    /// fixed by the mesh (the scan) or the hierarchy's top subtrees, the surface's elevations in
    /// chunks of 16,384 vertices; bit-identical to the serial result. Worth it from about 10⁵
    /// triangles.
    #[cfg(feature = "rayon")]
    pub const fn in_parallel(mut self) -> Self {
        self.parallel = true;
        self
    }

    /// The method.
    pub const fn method(&self) -> Method {
        self.method
    }

    /// The traversal.
    pub const fn traversal(&self) -> Traversal {
        self.traversal
    }

    /// Whether the work is split across rayon's thread pool.
    pub const fn is_parallel(&self) -> bool {
        self.parallel
    }
}

impl From<Method> for Query {
    fn from(method: Method) -> Self {
        Query::new(method)
    }
}
