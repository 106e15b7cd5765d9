//! The administrative REST API: login/logout, access rules, robot tokens, users and the
//! audit log, under `/api/v1/`.
//!
//! Design choice: every change goes through [`fleetlink_auth::Security`], never straight
//! to the store, so it is persisted, audited (with the caller as actor) and applied to
//! live connections at once, with no restart. Each admin handler first asks the
//! authorizer for [`Operation::Admin`] on the resource name (`/rules`, `/users`,
//! `/tokens`, `/audit`); a refusal is itself audited and answered 403. Bodies are parsed
//! here rather than by axum's extractors so every error, malformed JSON included, is a
//! JSON `{"error": "..."}` that names the problem. SQLite and argon2 work runs on the
//! blocking pool.
//!
//! `POST /api/v1/login` is the one public route: it is merged outside the
//! `require_identity` layer (see [`public_routes`]).

use std::collections::HashMap;
use std::sync::Arc;

use axum::body::Bytes;
use axum::extract::{ConnectInfo, Path, Query, Request, State};
use axum::http::{HeaderMap, StatusCode, header};
use axum::response::{IntoResponse, Response};
use axum::routing::{delete, get, post};
use axum::{Extension, Json};
use fleetlink_auth::audit::{AuditAction, AuditCursor, AuditQuery, MAX_PAGE};
use fleetlink_auth::store::TokenId;
use fleetlink_auth::{
    AuditRecord, AuthError, Credential, GroupName, Identity, Operation, RobotName, Rule, RuleId,
    Security, SecurityError, StoreError, UnixTime, UserName,
};
use serde::Deserialize;
use serde_json::{Value, json};

use super::caller::Caller;
use crate::connection::ConnMeta;
use crate::state::HubState;

/// Routes that need an authenticated caller (merged under `require_identity`).
pub fn routes() -> axum::Router<Arc<HubState>> {
    axum::Router::new()
        .route("/api/v1/logout", post(logout))
        .route(
            "/api/v1/rules",
            get(list_rules).post(add_rule).put(replace_rules),
        )
        .route("/api/v1/rules/{id}", delete(remove_rule))
        .route("/api/v1/robots/{name}/tokens", post(mint_robot_token))
        .route("/api/v1/tokens", get(list_tokens))
        .route("/api/v1/tokens/{id}", delete(revoke_token))
        .route("/api/v1/users", get(list_users).post(add_user))
        .route("/api/v1/users/{name}", delete(remove_user))
        .route("/api/v1/audit", get(audit))
}

/// Routes anyone may call: only login, which is rate-limited by the security core.
pub fn public_routes() -> axum::Router<Arc<HubState>> {
    axum::Router::new().route("/api/v1/login", post(login))
}

/// Why an API request failed; the response is `{"error": "<this text>"}`.
#[derive(Debug, thiserror::Error)]
pub enum ApiError {
    #[error("{0}")]
    BadRequest(String),
    #[error("{caller} may not administer {resource}")]
    Forbidden { caller: String, resource: String },
    #[error("{0}")]
    NotFound(String),
    #[error("{0}")]
    Conflict(String),
    #[error("{}", .0.public_message())]
    Auth(AuthError),
    #[error(transparent)]
    Security(#[from] SecurityError),
    #[error("the blocking task failed: {0}")]
    Join(#[from] tokio::task::JoinError),
}

impl From<StoreError> for ApiError {
    fn from(e: StoreError) -> ApiError {
        ApiError::Security(SecurityError::Store(e))
    }
}

impl ApiError {
    fn status(&self) -> StatusCode {
        match self {
            ApiError::BadRequest(_) => StatusCode::BAD_REQUEST,
            ApiError::Forbidden { .. } => StatusCode::FORBIDDEN,
            ApiError::NotFound(_) => StatusCode::NOT_FOUND,
            ApiError::Conflict(_) => StatusCode::CONFLICT,
            ApiError::Auth(e) => match e {
                AuthError::RateLimited { .. } => StatusCode::TOO_MANY_REQUESTS,
                AuthError::Oversized { .. }
                | AuthError::MalformedToken(_)
                | AuthError::WrongTokenKind { .. }
                | AuthError::BadName(_) => StatusCode::BAD_REQUEST,
                AuthError::Store(_) => StatusCode::SERVICE_UNAVAILABLE,
                _ => StatusCode::UNAUTHORIZED,
            },
            ApiError::Security(SecurityError::Import(_)) => StatusCode::BAD_REQUEST,
            ApiError::Security(SecurityError::Store(s)) => match s {
                s if s.is_unavailable() => StatusCode::SERVICE_UNAVAILABLE,
                StoreError::UserExists(_) => StatusCode::CONFLICT,
                StoreError::NoSuchUser(_) => StatusCode::NOT_FOUND,
                StoreError::PasswordHash(_) => StatusCode::BAD_REQUEST,
                _ => StatusCode::INTERNAL_SERVER_ERROR,
            },
            ApiError::Security(_) | ApiError::Join(_) => StatusCode::INTERNAL_SERVER_ERROR,
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let status = self.status();
        let mut res = (status, Json(json!({"error": self.to_string()}))).into_response();
        if let ApiError::Auth(AuthError::RateLimited { retry_after_secs }) = &self
            && let Ok(v) = header::HeaderValue::from_str(&retry_after_secs.max(&1).to_string())
        {
            res.headers_mut().insert(header::RETRY_AFTER, v);
        }
        if status.is_server_error() {
            tracing::warn!("admin API: {self}");
        }
        res
    }
}

type ApiResult = Result<Response, ApiError>;

/// Runs `f` with the security core on the blocking pool (SQLite, argon2).
async fn blocking<T: Send + 'static>(
    st: &HubState,
    f: impl FnOnce(&Security) -> Result<T, ApiError> + Send + 'static,
) -> Result<T, ApiError> {
    let sec = st.security.clone();
    tokio::task::spawn_blocking(move || f(&sec)).await?
}

/// Parses a JSON body into `T`, naming what was wrong with it.
fn json_body<T: serde::de::DeserializeOwned>(body: &Bytes, what: &str) -> Result<T, ApiError> {
    serde_json::from_slice(body).map_err(|e| ApiError::BadRequest(format!("invalid {what}: {e}")))
}

/// What a refused admin request was trying to do, for the audit record's action.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Intent {
    /// Read a listing (`GET`): refused as `access_denied`.
    Read,
    /// Change rules or credentials: refused as `rule_change` / `credential_change`.
    Change,
}

/// Refuses (403, audited) unless the caller may administer `resource`.
pub(crate) fn require_admin(
    st: &HubState,
    caller: &Identity,
    resource: &str,
) -> Result<(), ApiError> {
    require(st, caller, resource, Intent::Change)
}

/// Refuses (403, audited as `access_denied`) unless the caller may read the admin
/// resource `resource` (`/rules`, `/clients`, `/metrics`, ...).
pub(crate) fn require_read(
    st: &HubState,
    caller: &Identity,
    resource: &str,
) -> Result<(), ApiError> {
    require(st, caller, resource, Intent::Read)
}

fn require(
    st: &HubState,
    caller: &Identity,
    resource: &str,
    intent: Intent,
) -> Result<(), ApiError> {
    let action = match intent {
        Intent::Read => AuditAction::AccessDenied,
        Intent::Change if resource == "/rules" => AuditAction::RuleChange,
        Intent::Change if resource == "/recordings" => AuditAction::Recording,
        Intent::Change => AuditAction::CredentialChange,
    };
    require_or_audit(st, caller, resource, action)
}

/// Refuses (403, audited as `action`) unless the caller may administer `resource`.
pub(crate) fn require_admin_as(
    st: &HubState,
    caller: &Identity,
    resource: &str,
    action: AuditAction,
) -> Result<(), ApiError> {
    require_or_audit(st, caller, resource, action)
}

fn require_or_audit(
    st: &HubState,
    caller: &Identity,
    resource: &str,
    action: AuditAction,
) -> Result<(), ApiError> {
    if st
        .security
        .authz
        .decide(caller, resource, Operation::Admin)
        .allowed
    {
        return Ok(());
    }
    st.security.audit.record(
        AuditRecord::operation(caller, action, resource, None, false, UnixTime::now())
            .with_detail("admin API: not in the admin group and no admin rule"),
    );
    Err(ApiError::Forbidden {
        caller: caller.principal(),
        resource: resource.to_owned(),
    })
}

/// Records a refused rule change (a hostile or broken rule file) before answering 400.
fn refused_rules(st: &HubState, caller: &Identity, err: ApiError) -> ApiError {
    st.security.audit.record(
        AuditRecord::operation(
            caller,
            AuditAction::RuleChange,
            "/rules",
            None,
            false,
            UnixTime::now(),
        )
        .with_detail(err.to_string()),
    );
    err
}

fn created(v: Value) -> Response {
    (StatusCode::CREATED, Json(v)).into_response()
}

fn no_content() -> Response {
    StatusCode::NO_CONTENT.into_response()
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LoginBody {
    user: String,
    password: String,
}

/// `POST /api/v1/login` `{user, password}` → `{token, expires_at}`.
async fn login(
    State(st): State<Arc<HubState>>,
    ConnectInfo(peer): ConnectInfo<std::net::SocketAddr>,
    req: Request,
) -> ApiResult {
    let tls_name = req
        .extensions()
        .get::<ConnMeta>()
        .and_then(|m| m.tls_name.clone());
    let conn = crate::security::conn_info(peer, req.headers(), tls_name);
    let body = axum::body::to_bytes(req.into_body(), 64 * 1024)
        .await
        .map_err(|e| ApiError::BadRequest(format!("cannot read the body: {e}")))?;
    let b: LoginBody = json_body(&body, "login body (expected {\"user\", \"password\"})")?;
    let session = blocking(&st, move |sec| {
        sec.login(&b.user, &b.password, conn, UnixTime::now())
            .map_err(ApiError::Auth)
    })
    .await?;
    Ok(Json(json!({
        "token": session.token.expose(),
        "expires_at": session.expires_at,
        "principal": session.identity.principal(),
    }))
    .into_response())
}

/// `POST /api/v1/logout`: ends the session whose token authenticated this request.
async fn logout(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    headers: HeaderMap,
    uri: axum::http::Uri,
) -> ApiResult {
    let Credential::Bearer(token) = crate::security::request_credential(&headers, uri.query())
    else {
        return Err(ApiError::BadRequest(
            "logout needs the session token (Authorization: Bearer or ?token=)".into(),
        ));
    };
    blocking(&st, move |sec| {
        sec.logout(&me, &token, UnixTime::now())
            .map_err(ApiError::Auth)
    })
    .await?;
    Ok(no_content())
}

async fn list_rules(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> ApiResult {
    require_read(&st, &me, "/rules")?;
    let rules = blocking(&st, |sec| Ok(sec.store.list_rules()?)).await?;
    Ok(Json(json!({ "rules": rules })).into_response())
}

/// `POST /api/v1/rules` with one rule as JSON → `{"id": n}`.
async fn add_rule(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    body: Bytes,
) -> ApiResult {
    require_admin(&st, &me, "/rules")?;
    let rule: Rule = json_body(&body, "rule").map_err(|e| refused_rules(&st, &me, e))?;
    let id = blocking(&st, move |sec| {
        Ok(sec.add_rule(&me, rule, UnixTime::now())?)
    })
    .await?;
    Ok(created(json!({ "id": id })))
}

/// `PUT /api/v1/rules`: replaces every rule. JSON (`{"rules": [...]}` or a bare array)
/// when the content type says so, else the YAML rule file format.
async fn replace_rules(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    headers: HeaderMap,
    body: Bytes,
) -> ApiResult {
    require_admin(&st, &me, "/rules")?;
    let is_json = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.contains("json"));
    let rules = parse_rules(is_json, &body).map_err(|e| refused_rules(&st, &me, e))?;
    let n = blocking(&st, move |sec| {
        Ok(sec.replace_rules(&me, rules, UnixTime::now())?)
    })
    .await?;
    Ok(Json(json!({ "rules": n })).into_response())
}

fn parse_rules(is_json: bool, body: &Bytes) -> Result<Vec<Rule>, ApiError> {
    Ok(if is_json {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Body {
            Wrapped { rules: Vec<Rule> },
            Bare(Vec<Rule>),
        }
        // Untagged enums hide the cause; parse the likely shape first for a clear error.
        match serde_json::from_slice::<Body>(body) {
            Ok(Body::Wrapped { rules }) | Ok(Body::Bare(rules)) => rules,
            Err(_) => {
                #[derive(Deserialize)]
                #[serde(deny_unknown_fields)]
                struct Wrapped {
                    #[allow(dead_code)]
                    rules: Vec<Rule>,
                }
                let e = serde_json::from_slice::<Wrapped>(body)
                    .err()
                    .map_or_else(|| "unreadable".to_owned(), |e| e.to_string());
                return Err(ApiError::BadRequest(format!("invalid rules: {e}")));
            }
        }
    } else {
        let text = std::str::from_utf8(body)
            .map_err(|e| ApiError::BadRequest(format!("rules YAML is not UTF-8: {e}")))?;
        fleetlink_auth::acl::import_yaml(text)
            .map_err(|e| ApiError::Security(SecurityError::Import(e)))?
    })
}

async fn remove_rule(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(id): Path<String>,
) -> ApiResult {
    require_admin(&st, &me, "/rules")?;
    let id = RuleId(parse_id(&id, "rule")?);
    if blocking(&st, move |sec| {
        Ok(sec.remove_rule(&me, id, UnixTime::now())?)
    })
    .await?
    {
        Ok(no_content())
    } else {
        Err(ApiError::NotFound(format!("no rule {id}")))
    }
}

fn parse_id(text: &str, what: &str) -> Result<i64, ApiError> {
    let text = text.trim_start_matches('#');
    text.parse()
        .map_err(|_| ApiError::BadRequest(format!("{what} id {text:?} is not a number")))
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct MintBody {
    /// Absolute expiry, seconds since the epoch.
    #[serde(default)]
    expires_at: Option<UnixTime>,
    /// Or a lifetime from now.
    #[serde(default)]
    ttl_secs: Option<i64>,
}

/// `POST /api/v1/robots/{name}/tokens` → `{id, token, robot, expires_at}`; the token is
/// shown this once.
async fn mint_robot_token(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(name): Path<String>,
    body: Bytes,
) -> ApiResult {
    require_admin(&st, &me, "/tokens")?;
    let robot = RobotName::new(&name).map_err(|e| ApiError::BadRequest(e.to_string()))?;
    let b: MintBody = if body.is_empty() {
        MintBody::default()
    } else {
        json_body(
            &body,
            "token request (expected {\"expires_at\"} or {\"ttl_secs\"})",
        )?
    };
    let now = UnixTime::now();
    let expires = match (b.expires_at, b.ttl_secs) {
        (Some(_), Some(_)) => {
            return Err(ApiError::BadRequest(
                "give expires_at or ttl_secs, not both".into(),
            ));
        }
        (Some(t), None) => Some(t),
        (None, Some(s)) if s > 0 => Some(now.plus_secs(s)),
        (None, Some(s)) => {
            return Err(ApiError::BadRequest(format!(
                "ttl_secs must be positive, got {s}"
            )));
        }
        (None, None) => None,
    };
    let (token, id) = blocking(&st, move |sec| {
        let token = sec.add_robot_token(&me, &robot, expires, now)?;
        let id = sec.store.lookup_token(&token.hash())?.map(|r| r.id);
        Ok((token, id))
    })
    .await?;
    Ok(created(json!({
        "id": id,
        "robot": name,
        "token": token.expose(),
        "expires_at": expires,
    })))
}

/// `GET /api/v1/tokens`: robot, operator and session tokens (never their secrets).
async fn list_tokens(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> ApiResult {
    require_read(&st, &me, "/tokens")?;
    let tokens = blocking(&st, |sec| Ok(sec.store.list_tokens(None)?)).await?;
    Ok(Json(json!({ "tokens": tokens })).into_response())
}

async fn revoke_token(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(id): Path<String>,
) -> ApiResult {
    require_admin(&st, &me, "/tokens")?;
    let id = TokenId(parse_id(&id, "token")?);
    if blocking(&st, move |sec| {
        Ok(sec.revoke_token(&me, id, UnixTime::now())?)
    })
    .await?
    {
        Ok(no_content())
    } else {
        Err(ApiError::NotFound(format!("no unrevoked token #{}", id.0)))
    }
}

async fn list_users(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> ApiResult {
    require_read(&st, &me, "/users")?;
    let users = blocking(&st, |sec| Ok(sec.store.list_users()?)).await?;
    Ok(Json(json!({ "users": users })).into_response())
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct UserBody {
    name: String,
    password: String,
    #[serde(default)]
    groups: Vec<String>,
}

/// `POST /api/v1/users` `{name, password, groups}`.
async fn add_user(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    body: Bytes,
) -> ApiResult {
    require_admin(&st, &me, "/users")?;
    let b: UserBody = json_body(
        &body,
        "user (expected {\"name\", \"password\", \"groups\"})",
    )?;
    let name = UserName::new(&b.name)
        .map_err(|e| ApiError::BadRequest(format!("user name {:?}: {e}", b.name)))?;
    let groups = b
        .groups
        .iter()
        .map(|g| GroupName::new(g).map_err(|e| ApiError::BadRequest(format!("group {g:?}: {e}"))))
        .collect::<Result<Vec<_>, _>>()?;
    blocking(&st, move |sec| {
        Ok(sec.add_user(&me, &name, &b.password, &groups, UnixTime::now())?)
    })
    .await?;
    Ok(created(json!({ "name": b.name, "groups": b.groups })))
}

async fn remove_user(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(name): Path<String>,
) -> ApiResult {
    require_admin(&st, &me, "/users")?;
    let user = UserName::new(&name)
        .map_err(|e| ApiError::BadRequest(format!("user name {name:?}: {e}")))?;
    if blocking(&st, move |sec| {
        Ok(sec.remove_user(&me, &user, UnixTime::now())?)
    })
    .await?
    {
        Ok(no_content())
    } else {
        Err(ApiError::NotFound(format!("no user {name:?}")))
    }
}

/// `GET /api/v1/audit?principal=&action=&name=&name_regex=&allowed=&since=&until=&limit=&cursor=`
/// → `{records, next}`, newest first; pass `next` back as `cursor` for the next page.
async fn audit(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Query(params): Query<HashMap<String, String>>,
) -> ApiResult {
    require_read(&st, &me, "/audit")?;
    let q = audit_query(&params)?;
    let page = blocking(&st, move |sec| {
        // Records still in the writer's channel would be missing from the answer.
        sec.audit.flush();
        Ok(sec.store.query_audit(&q)?)
    })
    .await?;
    Ok(Json(json!(page)).into_response())
}

fn audit_query(p: &HashMap<String, String>) -> Result<AuditQuery, ApiError> {
    fn num(p: &HashMap<String, String>, k: &str) -> Result<Option<i64>, ApiError> {
        p.get(k)
            .map(|v| {
                v.parse()
                    .map_err(|_| ApiError::BadRequest(format!("{k}={v:?} is not an integer")))
            })
            .transpose()
    }
    const KNOWN: [&str; 10] = [
        "principal",
        "action",
        "name",
        "name_regex",
        "allowed",
        "since",
        "until",
        "limit",
        "cursor",
        "token",
    ];
    if let Some(k) = p.keys().find(|k| !KNOWN.contains(&k.as_str())) {
        return Err(ApiError::BadRequest(format!(
            "unknown audit filter {k:?} (known: {})",
            KNOWN[..9].join(", ")
        )));
    }
    let action = p
        .get("action")
        .map(|a| {
            AuditAction::parse(a)
                .ok_or_else(|| ApiError::BadRequest(format!("unknown audit action {a:?}")))
        })
        .transpose()?;
    let allowed = p
        .get("allowed")
        .map(|v| match v.as_str() {
            "true" => Ok(true),
            "false" => Ok(false),
            _ => Err(ApiError::BadRequest(format!(
                "allowed={v:?}: expected true or false"
            ))),
        })
        .transpose()?;
    let name_regex = p
        .get("name_regex")
        .map(|r| {
            fleetlink_auth::acl::NamePattern::new(r)
                .map_err(|e| ApiError::BadRequest(format!("name_regex: {e}")))
        })
        .transpose()?;
    let limit = num(p, "limit")?.unwrap_or(0);
    if !(0..=i64::from(MAX_PAGE)).contains(&limit) {
        return Err(ApiError::BadRequest(format!(
            "limit={limit}: expected 0..={}",
            MAX_PAGE
        )));
    }
    Ok(AuditQuery {
        principal: p.get("principal").cloned(),
        action,
        name_prefix: p.get("name").cloned(),
        name_regex,
        allowed,
        since: num(p, "since")?.map(UnixTime),
        until: num(p, "until")?.map(UnixTime),
        limit: limit as u32,
        after: num(p, "cursor")?.map(AuditCursor),
    })
}
