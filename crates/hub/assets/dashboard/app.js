var lu="fleetlink.token",cu="fleetlink.principal",Si={token(){return sessionStorage.getItem(lu)},principal(){return sessionStorage.getItem(cu)},set(n,e){sessionStorage.setItem(lu,n),sessionStorage.setItem(cu,e)},clear(){sessionStorage.removeItem(lu),sessionStorage.removeItem(cu)},wsUrl(){let n=location.protocol==="https:"?"wss:":"ws:",e=this.token();return`${n}//${location.host}/${e?`?token=${encodeURIComponent(e)}`:""}`}};var fr=class extends Error{constructor(t,i){super(i);this.status=t}status};async function gn(n,e={}){let t=new Headers(e.headers),i=Si.token();i&&t.set("Authorization",`Bearer ${i}`),e.body&&t.set("Content-Type","application/json");let s=await fetch(n,{...e,headers:t,cache:"no-store"}),r=await s.text(),o=null;try{o=r?JSON.parse(r):null}catch{o=r}if(!s.ok)throw new fr(s.status,o&&o.error||r||`HTTP ${s.status}`);return o}var vt={frames:{},poses:{},feedback:[],lastResult:null,lastServiceResponse:null,disabled:{},renders:0,cloudAgesMs:[],busyMs:{decode:0,cloudUnpack:0,cloudRender:0},markers:{drawn:0,shapes:0,byType:{},byNs:{}},mapToScreen:null,config:{loaded:!1,mayChange:!1,overlay:null,result:""},video:{topic:"",codec:"",width:0,height:0,decoded:0,errors:0,fallback:""}};function On(n){vt.frames[n]=(vt.frames[n]??0)+1}globalThis.fleetlink=vt;var xe={POS_INT:0,NEG_INT:1,BYTE_STRING:2,UTF8_STRING:3,ARRAY:4,MAP:5,TAG:6,SIMPLE_FLOAT:7},Mt={DATE_STRING:0,DATE_EPOCH:1,POS_BIGINT:2,NEG_BIGINT:3,DECIMAL_FRAC:4,BIGFLOAT:5,BASE64URL_EXPECTED:21,BASE64_EXPECTED:22,BASE16_EXPECTED:23,CBOR:24,URI:32,BASE64URL:33,BASE64:34,MIME:36,DATE_EPOCH_DAYS:100,SET:258,JSON:262,WTF8:273,SYMBOL:280,DATE_FULL:1004,REGEXP:21066,SELF_DESCRIBED:55799,INVALID_16:65535,INVALID_32:4294967295,INVALID_64:0xffffffffffffffffn},ct={ZERO:0,ONE:24,TWO:25,FOUR:26,EIGHT:27,INDEFINITE:31},Ki={FALSE:20,TRUE:21,NULL:22,UNDEFINED:23},Kt=class{static BREAK=Symbol.for("github.com/hildjj/cbor2/break");static ENCODED=Symbol.for("github.com/hildjj/cbor2/cbor-encoded");static LENGTH=Symbol.for("github.com/hildjj/cbor2/length")},Yr={MIN:-(2n**63n),MAX:2n**64n-1n};var tt=class n{static#e=new Map;tag;contents;constructor(e,t=void 0){this.tag=e,this.contents=t}get noChildren(){return!!n.#e.get(this.tag)?.noChildren}static registerDecoder(e,t,i){let s=this.#e.get(e);return this.#e.set(e,t),s&&("comment"in t||(t.comment=s.comment),"noChildren"in t||(t.noChildren=s.noChildren)),i&&!t.comment&&(t.comment=()=>`(${i})`),s}static clearDecoder(e){let t=this.#e.get(e);return this.#e.delete(e),t}static getDecoder(e){return this.#e.get(e)}static getAllDecoders(){return new Map(this.#e)}*[Symbol.iterator](){yield this.contents}push(e){return this.contents=e,1}decode(e){let t=e?.tags?.get(this.tag)??(e?.ignoreGlobalTags?void 0:n.#e.get(this.tag));return t?t(this,e):this}comment(e,t){let i=e?.tags?.get(this.tag)??(e?.ignoreGlobalTags?void 0:n.#e.get(this.tag));if(i?.comment)return i.comment(this,e,t)}toCBOR(){return[this.tag,this.contents]}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return`${this.tag}(${i(this.contents,t)})`}};function Os(n){if(n!=null&&typeof n=="object")return n[Kt.ENCODED]}function ip(n){if(n!=null&&typeof n=="object")return n[Kt.LENGTH]}function Fs(n,e){Object.defineProperty(n,Kt.ENCODED,{configurable:!0,enumerable:!1,value:e})}function Bs(n,e){let t=Object(n);return Fs(t,e),t}var hu=Symbol("CBOR_RANGES");function sp(n,e){Object.defineProperty(n,hu,{configurable:!1,enumerable:!1,writable:!1,value:e})}function Ko(n){return n[hu]}function Y_(n){return Ko(n)!==void 0}function Jo(n,e=0,t=n.length-1){let i=n.subarray(e,t),s=Ko(n);if(s){let r=[];for(let o of s)if(o[0]>=e&&o[0]+o[1]<=t){let a=[...o];a[0]-=e,r.push(a)}r.length&&sp(i,r)}return i}function ll(n){let e=Math.ceil(n.length/2),t=new Uint8Array(e);e--;for(let i=n.length,s=i-2;i>=0;i=s,s-=2,e--)t[e]=parseInt(n.substring(s,i),16);return t}function Fn(n){return n.reduce((e,t)=>e+t.toString(16).padStart(2,"0"),"")}function rp(n){let e=n.reduce((o,a)=>o+a.length,0),t=n.some(o=>Y_(o)),i=[],s=new Uint8Array(e),r=0;for(let o of n){if(!(o instanceof Uint8Array))throw new TypeError(`Invalid array: ${o}`);if(s.set(o,r),t){let a=o[hu]??[[0,o.length]];for(let l of a)l[0]+=r;i.push(...a)}r+=o.length}return t&&sp(s,i),s}function jo(n){let e=atob(n);return Uint8Array.from(e,t=>t.codePointAt(0))}var Z_={"-":"+",_:"/"};function op(n){let e=n.replace(/[_-]/g,t=>Z_[t]);return jo(e.padEnd(Math.ceil(e.length/4)*4,"="))}function ap(){let n=new Uint8Array(4),e=new Uint32Array(n.buffer);return!((e[0]=1)&n[0])}function uu(n){let e="";for(let t of n){let i=t.codePointAt(0)?.toString(16).padStart(4,"0");e&&(e+=", "),e+=`U+${i}`}return e}var Qo=class{#e=new Map;registerEncoder(e,t){let i=this.#e.get(e);return this.#e.set(e,t),i}get(e){return this.#e.get(e)}delete(e){return this.#e.delete(e)}clear(){this.#e.clear()}};function cl(n,e){let[t,i,s]=n,[r,o,a]=e,l=Math.min(s.length,a.length);for(let c=0;c<l;c++){let h=s[c]-a[c];if(h!==0)return h}return 0}var Zr=class n{static defaultOptions={chunkSize:4096};#e;#t=[];#n=null;#i=0;#s=0;constructor(e={}){if(this.#e={...n.defaultOptions,...e},this.#e.chunkSize<8)throw new RangeError(`Expected size >= 8, got ${this.#e.chunkSize}`);this.#r()}get length(){return this.#s}read(){this.#l();let e=new Uint8Array(this.#s),t=0;for(let i of this.#t)e.set(i,t),t+=i.length;return this.#r(),e}write(e){let t=e.length;t>this.#c()?(this.#l(),t>this.#e.chunkSize?(this.#t.push(e),this.#r()):(this.#r(),this.#t[this.#t.length-1].set(e),this.#i=t)):(this.#t[this.#t.length-1].set(e,this.#i),this.#i+=t),this.#s+=t}writeUint8(e){this.#o(1),this.#n.setUint8(this.#i,e),this.#a(1)}writeUint16(e,t=!1){this.#o(2),this.#n.setUint16(this.#i,e,t),this.#a(2)}writeUint32(e,t=!1){this.#o(4),this.#n.setUint32(this.#i,e,t),this.#a(4)}writeBigUint64(e,t=!1){this.#o(8),this.#n.setBigUint64(this.#i,e,t),this.#a(8)}writeInt16(e,t=!1){this.#o(2),this.#n.setInt16(this.#i,e,t),this.#a(2)}writeInt32(e,t=!1){this.#o(4),this.#n.setInt32(this.#i,e,t),this.#a(4)}writeBigInt64(e,t=!1){this.#o(8),this.#n.setBigInt64(this.#i,e,t),this.#a(8)}writeFloat32(e,t=!1){this.#o(4),this.#n.setFloat32(this.#i,e,t),this.#a(4)}writeFloat64(e,t=!1){this.#o(8),this.#n.setFloat64(this.#i,e,t),this.#a(8)}clear(){this.#s=0,this.#t=[],this.#r()}#r(){let e=new Uint8Array(this.#e.chunkSize);this.#t.push(e),this.#i=0,this.#n=new DataView(e.buffer,e.byteOffset,e.byteLength)}#l(){if(this.#i===0){this.#t.pop();return}let e=this.#t.length-1;this.#t[e]=this.#t[e].subarray(0,this.#i),this.#i=0,this.#n=null}#c(){let e=this.#t.length-1;return this.#t[e].length-this.#i}#o(e){this.#c()<e&&(this.#l(),this.#r())}#a(e){this.#i+=e,this.#s+=e}};var du=1n<<15n,ea=0b11111n<<10n,pp=1n<<9n,mp=pp-1n,lp=pp|mp,fu=1n<<31n,ta=0b11111111n<<23n,gp=1n<<22n,_p=gp-1n,cp=gp|_p,hl=1n<<63n,ds=0b11111111111n<<52n,na=1n<<51n,ul=na-1n,hp=na|ul,up=ul-(mp<<42n),dp=ul-(_p<<29n),K_={2:"0b",8:"0o",16:"0x"},yp=(n=>(n[n.NATURAL=-2]="NATURAL",n[n.UNKNOWN=-1]="UNKNOWN",n[n.F16=2]="F16",n[n.F32=4]="F32",n[n.F64=8]="F64",n))(yp||{});function fp(n,e,t,i){let s="nan'";return n.quiet||(s+="!"),n.sign===-1&&(s+="-"),s+=i(Math.abs(n.payload),t),s+="'",s+=n.encodingIndicator,s}var ia=class extends Number{#e;#t=-1;constructor(e,t=!0,i=-1){super(NaN);let s=e;if(typeof e=="number"){if(!Number.isSafeInteger(e))throw new Error(`Invalid NAN payload: ${e}`);e=BigInt(e);let r=0n;if(e<0&&(r=hl,e=-e),e>=na)throw new Error(`Payload too large: ${s}`);let o=t?na:0n;switch(this.#e=r|ds|o|e,i){case-2:throw new Error("NAN_SIZE.NATURAL only valid for bigint constructor");case-1:i=this.preferredSize;break;case 2:if(this.#e&up)throw new Error("Invalid size for payload");break;case 4:if(this.#e&dp)throw new Error("Invalid size for payload");break;case 8:break;default:throw new Error(`Invalid size: ${i}`)}this.#t=i}else if(typeof e=="bigint"){let r=-1;if((e&ds)===ds)this.#e=e,r=8;else if((e&ta)===ta){let o=(e&fu)<<32n;this.#e=o|ds|(e&cp)<<29n,r=4}else if((e&ea)===ea){let o=(e&du)<<48n;this.#e=o|ds|(e&lp)<<42n,r=2}else throw new Error(`Invalid raw NaN value: ${e}`);if(i===-1)this.#t=this.preferredSize;else if(i===-2)this.#t=r;else{if(i<r)throw new Error("Invalid bigint NaN size");this.#t=i}}else{let r=new DataView(e.buffer,e.byteOffset,e.byteLength);switch(e.length){case 3:{if(e[0]!==249)throw new Error("Invalid CBOR encoding for half float");let o=BigInt(r.getUint16(1,!1));if((o&ea)!==ea)throw new Error("Not a NaN");let a=(o&du)<<48n;this.#e=a|ds|(o&lp)<<42n,this.#t=2;break}case 5:{if(e[0]!==250)throw new Error("Invalid CBOR encoding for single float");let o=BigInt(r.getUint32(1,!1));if((o&ta)!==ta)throw new Error("Not a NaN");let a=(o&fu)<<32n;this.#e=a|ds|(o&cp)<<29n,this.#t=4;break}case 9:{if(e[0]!==251)throw new Error("Invalid CBOR encoding for double float");if(this.#e=r.getBigUint64(1,!1),(this.#e&ds)!==ds)throw new Error("Not a NaN (NaNaN)");this.#t=8;break}default:throw new RangeError(`Invalid NAN size (should be 2, 4, or 8): ${e.length-1}`)}}if(!this.payload&&!this.quiet)throw new Error("Signalling NaN with zero payload")}get bytes(){let e=new ArrayBuffer(this.#t+1),t=new DataView(e);switch(this.#t){case 2:{t.setUint8(0,249);let i=(this.#e&hl?du:0n)|ea|(this.#e&hp)>>42n;t.setUint16(1,Number(i),!1);break}case 4:{t.setUint8(0,250);let i=(this.#e&hl?fu:0n)|ta|(this.#e&hp)>>29n;t.setUint32(1,Number(i),!1);break}case 8:t.setUint8(0,251),t.setBigUint64(1,this.#e);break}return new Uint8Array(e)}get quiet(){return!!(this.#e&na)}get sign(){return this.#e&hl?-1:1}get payload(){return Number(this.#e&ul)*this.sign}get raw(){return this.#e}get encodingIndicator(){switch(this.#t){case 2:return"_1";case 4:return"_2"}return"_3"}get size(){return this.#t}get preferredSize(){return(this.#e&up)===0n?2:(this.#e&dp)===0n?4:8}get isShortestEncoding(){return this.preferredSize===this.#t}toCBOR(e){e.write(this.bytes)}toString(e=10){return fp(this,1,{},t=>(K_[e]??"")+t.toString(e))}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return fp(this,e,t,i)}};function pu(n,e=0,t=!1){let i=n[e]&128?-1:1,s=(n[e]&124)>>2,r=(n[e]&3)<<8|n[e+1];if(s===0){if(t&&r!==0)throw new Error(`Unwanted subnormal: ${i*5960464477539063e-23*r}`);return i*5960464477539063e-23*r}else if(s===31)return r?NaN:i*(1/0);return i*2**(s-25)*(1024+r)}function dl(n){let e=new DataView(new ArrayBuffer(4));e.setFloat32(0,n,!1);let t=e.getUint32(0,!1);if((t&8191)!==0)return null;let i=t>>16&32768,s=t>>23&255,r=t&8388607;if(!(s===0&&r===0))if(s>=113&&s<=142)i+=(s-112<<10)+(r>>13);else if(s>=103&&s<113){if(r&(1<<126-s)-1)return null;i+=r+8388608>>126-s}else if(s===255)i|=31744,i|=r>>13;else return null;return i}function xp(n){if(n!==0){let e=new ArrayBuffer(8),t=new DataView(e);t.setFloat64(0,n,!1);let i=t.getBigUint64(0,!1);if((i&0x7ff0000000000000n)===0n)return i&0x8000000000000000n?-0:0}return n}function vp(n){switch(n.length){case 2:pu(n,0,!0);break;case 4:{let e=new DataView(n.buffer,n.byteOffset,n.byteLength),t=e.getUint32(0,!1);if((t&2139095040)===0&&t&8388607)throw new Error(`Unwanted subnormal: ${e.getFloat32(0,!1)}`);break}case 8:{let e=new DataView(n.buffer,n.byteOffset,n.byteLength),t=e.getBigUint64(0,!1);if((t&0x7ff0000000000000n)===0n&&t&0x000fffffffffffn)throw new Error(`Unwanted subnormal: ${e.getFloat64(0,!1)}`);break}default:throw new TypeError(`Bad input to isSubnormal: ${n}`)}}var sa=class extends TypeError{code="ERR_ENCODING_INVALID_ENCODED_DATA";constructor(){super("The encoded data was not valid for encoding wtf-8")}},fl=class extends RangeError{code="ERR_ENCODING_NOT_SUPPORTED";constructor(e){super(`Invalid encoding: "${e}"`)}};var pl=new Uint8Array(0);var mu=55296,bp=56320,Sp=65533,ml="wtf-8";function j_(n){return n&&typeof n=="object"&&!(n instanceof ArrayBuffer)&&!(n instanceof SharedArrayBuffer)&&n.buffer instanceof ArrayBuffer}function Q_(n){return n?n instanceof Uint8Array?n:j_(n)?new Uint8Array(n.buffer,n.byteOffset,n.byteLength):new Uint8Array(n):pl}var ey=[0,0,0,0,0,0,0,0,-1,-1,-1,-1,1,1,2,3],pr=class n{static DEFAULT_BUFFERSIZE=4096;encoding=ml;fatal;ignoreBOM;bufferSize;#e=0;#t=0;#n=0;#i=!0;#s;constructor(e="wtf8",t=void 0){if(e.toLowerCase().replace("-","")!=="wtf8")throw new fl(e);if(this.fatal=!!t?.fatal,this.ignoreBOM=!!t?.ignoreBOM,this.bufferSize=Math.floor(t?.bufferSize??n.DEFAULT_BUFFERSIZE),isNaN(this.bufferSize)||this.bufferSize<1)throw new RangeError(`Invalid buffer size: ${t?.bufferSize}`);this.#s=new Uint16Array(this.bufferSize)}decode(e,t){let i=!!t?.stream,s=Q_(e),r=[],o=this.#s,a=this.bufferSize-3,l=0,c=()=>{if(this.#t=0,this.#e=0,this.#n=0,this.fatal)throw new sa;o[l++]=Sp},h=()=>{let u=this.#n;for(let m=0;m<u;m++)c()},d=u=>{if(this.#e===0)switch(ey[u>>4]){case-1:c();break;case 0:o[l++]=u;break;case 1:this.#t=u&31,(this.#t&30)===0?c():(this.#e=1,this.#n=1);break;case 2:this.#t=u&15,this.#e=2,this.#n=1;break;case 3:u&8?c():(this.#t=u&7,this.#e=3,this.#n=1);break}else{if((u&192)!==128||this.#n===1&&this.#e===2&&this.#t===0&&(u&32)===0||this.#e===3&&this.#t===0&&(u&48)===0)return h(),d(u);if(this.#t=this.#t<<6|u&63,this.#n++,--this.#e===0){if(this.ignoreBOM||!this.#i||this.#t!==65279)if(this.#t<65536)o[l++]=this.#t;else{let m=this.#t-65536;o[l++]=m>>>10&1023|mu,o[l++]=m&1023|bp}this.#t=0,this.#n=0,this.#i=!1}}};for(let u of s)l>=a&&(r.push(String.fromCharCode.apply(null,o.subarray(0,l))),l=0),d(u);return i||(this.#i=!0,(this.#t||this.#e)&&h()),l>0&&r.push(String.fromCharCode.apply(null,o.subarray(0,l))),r.join("")}};function ty(n){let e=0;for(let t of n){let i=t.codePointAt(0);i<128?e++:i<2048?e+=2:i<65536?e+=3:e+=4}return e}var Kr=class{encoding=ml;encode(e){if(!e)return pl;let t=new Uint8Array(ty(String(e)));return this.encodeInto(e,t),t}encodeInto(e,t){let i=String(e),s=i.length,r=t.length,o=0,a=0;for(a=0;a<s;a++){let l=i.codePointAt(a);if(l<128){if(o>=r)break;t[o++]=l}else if(l<2048){if(o>=r-1)break;t[o++]=192|l>>6,t[o++]=128|l&63}else if(l<65536){if(o>=r-2)break;t[o++]=224|l>>12,t[o++]=128|l>>6&63,t[o++]=128|l&63}else{if(o>=r-3)break;t[o++]=240|l>>18,t[o++]=128|l>>12&63,t[o++]=128|l>>6&63,t[o++]=128|l&63,a++}}return{read:a,written:o}}};var{ENCODED:p1}=Kt,Mp=xe.SIMPLE_FLOAT<<5|ct.TWO,ny=xe.SIMPLE_FLOAT<<5|ct.FOUR,iy=xe.SIMPLE_FLOAT<<5|ct.EIGHT,sy=xe.SIMPLE_FLOAT<<5|Ki.TRUE,ry=xe.SIMPLE_FLOAT<<5|Ki.FALSE,oy=xe.SIMPLE_FLOAT<<5|Ki.UNDEFINED,ay=xe.SIMPLE_FLOAT<<5|Ki.NULL,ly=new TextEncoder,cy=new Kr,_l={...Zr.defaultOptions,avoidInts:!1,cde:!1,collapseBigInts:!0,dateTag:Mt.DATE_EPOCH,dcbor:!1,float64:!1,flushToZero:!1,forceEndian:null,ignoreOriginalEncoding:!1,largeNegativeAsBigInt:!1,reduceUnsafeNumbers:!1,rejectBigInts:!1,rejectCustomSimples:!1,rejectDuplicateKeys:!1,rejectFloats:!1,rejectUndefined:!1,simplifyNegativeZero:!1,sortKeys:null,stringNormalization:null,types:null,wtf8:!1,ignoreGlobalTags:!1},_u={cde:!0,ignoreOriginalEncoding:!0,sortKeys:cl},wp={..._u,dcbor:!0,largeNegativeAsBigInt:!0,reduceUnsafeNumbers:!0,rejectCustomSimples:!0,rejectDuplicateKeys:!0,rejectUndefined:!0,simplifyNegativeZero:!0,stringNormalization:"NFC"};function Ep(n){let e=n<0;return typeof n=="bigint"?[e?-n-1n:n,e]:[e?-n-1:n,e]}function gu(n,e,t){if(t.rejectFloats)throw new Error(`Attempt to encode an unwanted floating point number: ${n}`);if(isNaN(n))e.writeUint8(Mp),e.writeUint16(32256);else if(!t.float64&&Math.fround(n)===n){let i=dl(n);i===null?(e.writeUint8(ny),e.writeFloat32(n)):(e.writeUint8(Mp),e.writeUint16(i))}else e.writeUint8(iy),e.writeFloat64(n)}function Qn(n,e,t){let[i,s]=Ep(n);if(s&&t)throw new TypeError(`Negative size: ${n}`);t??=s?xe.NEG_INT:xe.POS_INT,t<<=5,i<24?e.writeUint8(t|i):i<=255?(e.writeUint8(t|ct.ONE),e.writeUint8(i)):i<=65535?(e.writeUint8(t|ct.TWO),e.writeUint16(i)):i<=4294967295?(e.writeUint8(t|ct.FOUR),e.writeUint32(i)):(e.writeUint8(t|ct.EIGHT),e.writeBigUint64(BigInt(i)))}function mr(n,e,t){typeof n=="number"?Qn(n,e,xe.TAG):typeof n=="object"&&!t.ignoreOriginalEncoding&&Kt.ENCODED in n?e.write(n[Kt.ENCODED]):n<=Number.MAX_SAFE_INTEGER?Qn(Number(n),e,xe.TAG):(e.writeUint8(xe.TAG<<5|ct.EIGHT),e.writeBigUint64(BigInt(n)))}function Tp(n,e,t){let[i,s]=Ep(n);if(t.collapseBigInts&&(!t.largeNegativeAsBigInt||n>=-0x8000000000000000n)){if(i<=0xffffffffn){Qn(Number(n),e);return}if(i<=0xffffffffffffffffn){let c=(s?xe.NEG_INT:xe.POS_INT)<<5;e.writeUint8(c|ct.EIGHT),e.writeBigUint64(i);return}}if(t.rejectBigInts)throw new Error(`Attempt to encode unwanted bigint: ${n}`);let r=s?Mt.NEG_BIGINT:Mt.POS_BIGINT,o=i.toString(16),a=o.length%2?"0":"";mr(r,e,t);let l=ll(a+o);Qn(l.length,e,xe.BYTE_STRING),e.write(l)}function hy(n,e,t){t.flushToZero&&(n=xp(n)),Object.is(n,-0)?t.simplifyNegativeZero?t.avoidInts?gu(0,e,t):Qn(0,e):gu(n,e,t):!t.avoidInts&&Number.isSafeInteger(n)?Qn(n,e):t.reduceUnsafeNumbers&&Math.floor(n)===n&&n>=Yr.MIN&&n<=Yr.MAX?Tp(BigInt(n),e,t):gu(n,e,t)}function Ap(n,e,t){let i=t.stringNormalization?n.normalize(t.stringNormalization):n;if(t.wtf8&&!n.isWellFormed()){let s=cy.encode(i);mr(Mt.WTF8,e,t),Qn(s.length,e,xe.BYTE_STRING),e.write(s)}else{let s=ly.encode(i);Qn(s.length,e,xe.UTF8_STRING),e.write(s)}}function uy(n,e,t){let i=n;yl(i,i.length,xe.ARRAY,e,t);for(let s of i)ks(s,e,t)}function dy(n,e){Qn(n.length,e,xe.BYTE_STRING),e.write(n)}var gl=new Qo;gl.registerEncoder(Array,uy),gl.registerEncoder(Uint8Array,dy);function nn(n,e){return gl.registerEncoder(n,e)}function yl(n,e,t,i,s){let r=ip(n);r&&!s.ignoreOriginalEncoding?i.write(r):Qn(e,i,t)}function fy(n,e,t){if(n===null){e.writeUint8(ay);return}if(!t.ignoreOriginalEncoding&&Kt.ENCODED in n){e.write(n[Kt.ENCODED]);return}let i=n.constructor;if(i){let r=t.types?.get(i)??(t.ignoreGlobalTags?void 0:gl.get(i));if(r){let o=r(n,e,t);if(o!==void 0){if(!Array.isArray(o)||o.length!==2)throw new Error("Invalid encoder return value");(typeof o[0]=="bigint"||isFinite(Number(o[0])))&&mr(o[0],e,t),ks(o[1],e,t)}return}}if(typeof n.toCBOR=="function"){let r=n.toCBOR(e,t);r&&((typeof r[0]=="bigint"||isFinite(Number(r[0])))&&mr(r[0],e,t),ks(r[1],e,t));return}if(typeof n.toJSON=="function"){ks(n.toJSON(),e,t);return}let s=Object.entries(n).map(r=>[r[0],r[1],zs(r[0],t)]);t.sortKeys&&s.sort(t.sortKeys),yl(n,s.length,xe.MAP,e,t);for(let[r,o,a]of s)e.write(a),ks(o,e,t)}function py(n,e,t){if(!n.description||n!==Symbol.for(n.description))throw new TypeError(`Private or empty symbol: ${n.toString()}`);mr(280,e,t),Ap(n.description,e,t)}function ks(n,e,t){switch(typeof n){case"number":hy(n,e,t);break;case"bigint":Tp(n,e,t);break;case"string":Ap(n,e,t);break;case"boolean":e.writeUint8(n?sy:ry);break;case"undefined":if(t.rejectUndefined)throw new Error("Attempt to encode unwanted undefined.");e.writeUint8(oy);break;case"object":fy(n,e,t);break;case"symbol":py(n,e,t);break;default:throw new TypeError(`Unknown type: ${typeof n}, ${String(n)}`)}}function zs(n,e={}){let t={..._l};e.dcbor?Object.assign(t,wp):e.cde&&Object.assign(t,_u),Object.assign(t,e);let i=new Zr(t);return ks(n,i,t),i.read()}var gr=(n=>(n[n.NEVER=-1]="NEVER",n[n.PREFERRED=0]="PREFERRED",n[n.ALWAYS=1]="ALWAYS",n))(gr||{});var Ii=class n{static KnownSimple=new Map([[Ki.FALSE,!1],[Ki.TRUE,!0],[Ki.NULL,null],[Ki.UNDEFINED,void 0]]);value;constructor(e){this.value=e}static create(e){return n.KnownSimple.has(e)?n.KnownSimple.get(e):new n(e)}toCBOR(e,t){if(t.rejectCustomSimples)throw new Error(`Cannot encode non-standard Simple value: ${this.value}`);Qn(this.value,e,xe.SIMPLE_FLOAT)}toString(){return`simple(${this.value})`}decode(){return n.KnownSimple.has(this.value)?n.KnownSimple.get(this.value):this}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return`simple(${i(this.value,t)})`}};var my=new TextDecoder("utf8",{fatal:!0,ignoreBOM:!0}),Ji=class n{static defaultOptions={maxDepth:1024,encoding:"hex",requirePreferred:!1};#e;#t;#n=0;#i;constructor(e,t){if(this.#i={...n.defaultOptions,...t},typeof e=="string")switch(this.#i.encoding){case"hex":this.#e=ll(e);break;case"base64":this.#e=jo(e);break;default:throw new TypeError(`Encoding not implemented: "${this.#i.encoding}"`)}else this.#e=e;this.#t=new DataView(this.#e.buffer,this.#e.byteOffset,this.#e.byteLength)}toHere(e){return Jo(this.#e,e,this.#n)}*[Symbol.iterator](){if(yield*this.#s(0),this.#n!==this.#e.length)throw new Error("Extra data in input")}*seq(){for(;this.#n<this.#e.length;)yield*this.#s(0)}*#s(e){if(e++>this.#i.maxDepth)throw new Error(`Maximum depth ${this.#i.maxDepth} exceeded`);let t=this.#n,i=this.#t.getUint8(this.#n++),s=i>>5,r=i&31,o=r,a=!1,l=0;switch(r){case ct.ONE:if(l=1,o=this.#t.getUint8(this.#n),s===xe.SIMPLE_FLOAT){if(o<32)throw new Error(`Invalid simple encoding in extra byte: ${o}`);a=!0}else if(this.#i.requirePreferred&&o<24)throw new Error(`Unexpectedly long integer encoding (1) for ${o}`);break;case ct.TWO:if(l=2,s===xe.SIMPLE_FLOAT)o=pu(this.#e,this.#n);else if(o=this.#t.getUint16(this.#n,!1),this.#i.requirePreferred&&o<=255)throw new Error(`Unexpectedly long integer encoding (2) for ${o}`);break;case ct.FOUR:if(l=4,s===xe.SIMPLE_FLOAT)o=this.#t.getFloat32(this.#n,!1);else if(o=this.#t.getUint32(this.#n,!1),this.#i.requirePreferred&&o<=65535)throw new Error(`Unexpectedly long integer encoding (4) for ${o}`);break;case ct.EIGHT:{if(l=8,s===xe.SIMPLE_FLOAT)o=this.#t.getFloat64(this.#n,!1);else if(o=this.#t.getBigUint64(this.#n,!1),o<=Number.MAX_SAFE_INTEGER&&(o=Number(o)),this.#i.requirePreferred&&o<=4294967295)throw new Error(`Unexpectedly long integer encoding (8) for ${o}`);break}case 28:case 29:case 30:throw new Error(`Additional info not implemented: ${r}`);case ct.INDEFINITE:switch(s){case xe.POS_INT:case xe.NEG_INT:case xe.TAG:throw new Error(`Invalid indefinite encoding for MT ${s}`);case xe.SIMPLE_FLOAT:yield[s,r,Kt.BREAK,t,0];return}o=1/0;break;default:a=!0}switch(this.#n+=l,s){case xe.POS_INT:yield[s,r,o,t,l];break;case xe.NEG_INT:yield[s,r,typeof o=="bigint"?-1n-o:-1-Number(o),t,l];break;case xe.BYTE_STRING:o===1/0?yield*this.#l(s,e,t):yield[s,r,this.#r(o),t,o];break;case xe.UTF8_STRING:o===1/0?yield*this.#l(s,e,t):yield[s,r,my.decode(this.#r(o)),t,o];break;case xe.ARRAY:if(o===1/0)yield*this.#l(s,e,t,!1);else{let c=Number(o);yield[s,r,c,t,l];for(let h=0;h<c;h++)yield*this.#s(e+1)}break;case xe.MAP:if(o===1/0)yield*this.#l(s,e,t,!1);else{let c=Number(o);yield[s,r,c,t,l];for(let h=0;h<c;h++)yield*this.#s(e),yield*this.#s(e)}break;case xe.TAG:yield[s,r,o,t,l],yield*this.#s(e);break;case xe.SIMPLE_FLOAT:{let c=o;a&&(o=Ii.create(Number(o))),yield[s,r,o,t,c];break}}}#r(e){let t=Jo(this.#e,this.#n,this.#n+=e);if(t.length!==e)throw new Error(`Unexpected end of stream reading ${e} bytes, got ${t.length}`);return t}*#l(e,t,i,s=!0){for(yield[e,ct.INDEFINITE,1/0,i,1/0];;){let r=this.#s(t),o=r.next(),[a,l,c]=o.value;if(c===Kt.BREAK){yield o.value,r.next();return}if(s){if(a!==e)throw new Error(`Unmatched major type.  Expected ${e}, got ${a}.`);if(l===ct.INDEFINITE)throw new Error("New stream started in typed stream")}yield o.value,yield*r}}};var gy=new Map([[ct.ZERO,1],[ct.ONE,2],[ct.TWO,3],[ct.FOUR,5],[ct.EIGHT,9]]),_y=new Uint8Array(0);function yy(n,e){return!e.boxed&&!e.preferMap&&n.every(([t])=>typeof t=="string")?Object.fromEntries(n):new Map(n)}var _n=class n{static defaultDecodeOptions={...Ji.defaultOptions,ParentType:n,boxed:!1,cde:!1,dcbor:!1,diagnosticSizes:gr.PREFERRED,collapseBigInts:!1,convertUnsafeIntsToFloat:!1,createObject:yy,keepNanPayloads:!1,pretty:!1,preferBigInt:!1,preferMap:!1,rejectLargeNegatives:!1,rejectBigInts:!1,rejectDuplicateKeys:!1,rejectFloats:!1,rejectInts:!1,rejectLongLoundNaN:!1,rejectLongFloats:!1,rejectNegativeZero:!1,rejectSimple:!1,rejectStreaming:!1,rejectStringsNotNormalizedAs:null,rejectSubnormals:!1,rejectUndefined:!1,rejectUnsafeFloatInts:!1,saveOriginal:!1,sortKeys:null,tags:null,ignoreGlobalTags:!1};static cdeDecodeOptions={cde:!0,rejectStreaming:!0,requirePreferred:!0,sortKeys:cl};static dcborDecodeOptions={...this.cdeDecodeOptions,dcbor:!0,convertUnsafeIntsToFloat:!0,rejectDuplicateKeys:!0,rejectLargeNegatives:!0,rejectLongLoundNaN:!0,rejectLongFloats:!0,rejectNegativeZero:!0,rejectSimple:!0,rejectUndefined:!0,rejectUnsafeFloatInts:!0,rejectStringsNotNormalizedAs:"NFC"};parent;mt;ai;left;offset;count=0;children=[];depth=0;#e;#t=null;constructor(e,t,i,s){if([this.mt,this.ai,,this.offset]=e,this.left=t,this.parent=i,this.#e=s,i&&(this.depth=i.depth+1),this.mt===xe.MAP&&(this.#e.sortKeys||this.#e.rejectDuplicateKeys)&&(this.#t=[]),this.#e.rejectStreaming&&this.ai===ct.INDEFINITE)throw new Error("Streaming not supported")}get isStreaming(){return this.left===1/0}get done(){return this.left===0}static create(e,t,i,s){let[r,o,a,l]=e;switch(r){case xe.POS_INT:case xe.NEG_INT:{if(i.rejectInts)throw new Error(`Unexpected integer: ${a}`);if(i.rejectLargeNegatives&&a<-0x8000000000000000n)throw new Error(`Invalid 65bit negative number: ${a}`);let c=a;return i.preferBigInt?c=BigInt(c):i.convertUnsafeIntsToFloat&&c>=Yr.MIN&&c<=Yr.MAX&&(c=Number(a)),i.boxed?Bs(c,s.toHere(l)):c}case xe.SIMPLE_FLOAT:if(o>ct.ONE){if(typeof a=="symbol")return a;if(i.rejectFloats)throw new Error(`Decoding unwanted floating point number: ${a}`);if(i.rejectNegativeZero&&Object.is(a,-0))throw new Error("Decoding negative zero");if(isNaN(a)){let c=s.toHere(l),h=new ia(c);if(i.rejectLongLoundNaN){if(h.payload||c.length>3)throw new Error(`Invalid NaN encoding: "${Fn(c)}"`)}else if(i.keepNanPayloads&&(h.payload||h.sign===-1)){if(i.rejectLongFloats&&!h.isShortestEncoding)throw new Error(`NaN should have been encoded shorter: ${a}`);return h}}if(i.rejectSubnormals&&vp(s.toHere(l+1)),i.rejectLongFloats){let c=zs(a,{chunkSize:9,reduceUnsafeNumbers:i.rejectUnsafeFloatInts});if(c[0]>>5!==r)throw new Error(`Should have been encoded as int, not float: ${a}`);if(c.length<gy.get(o))throw new Error(`Number should have been encoded shorter: ${a}`)}if(typeof a=="number"&&i.boxed)return Bs(a,s.toHere(l))}else{if(i.rejectSimple&&a instanceof Ii)throw new Error(`Invalid simple value: ${a}`);if(i.rejectUndefined&&a===void 0)throw new Error("Unexpected undefined")}return a;case xe.BYTE_STRING:case xe.UTF8_STRING:if(a===1/0)return new i.ParentType(e,1/0,t,i);if(i.rejectStringsNotNormalizedAs&&typeof a=="string"){let c=a.normalize(i.rejectStringsNotNormalizedAs);if(a!==c)throw new Error(`String not normalized as "${i.rejectStringsNotNormalizedAs}", got [${uu(a)}] instead of [${uu(c)}]`)}return i.boxed?Bs(a,s.toHere(l)):a;case xe.ARRAY:return new i.ParentType(e,a,t,i);case xe.MAP:return new i.ParentType(e,a*2,t,i);case xe.TAG:{let c=new i.ParentType(e,1,t,i);return c.children=new tt(a),c}}throw new TypeError(`Invalid major type: ${r}`)}static decodeToEncodeOpts(e){return{..._l,avoidInts:e.rejectInts,float64:!e.rejectLongFloats,flushToZero:e.rejectSubnormals,largeNegativeAsBigInt:e.rejectLargeNegatives,sortKeys:e.sortKeys}}push(e,t,i){if(this.children.push(e),this.#t){let s=Os(e)||t.toHere(i);this.#t.push(s)}return--this.left}replaceLast(e,t,i){let s,r=-1/0;if(this.children instanceof tt?(r=0,s=this.children.contents,this.children.contents=e):(r=this.children.length-1,s=this.children[r],this.children[r]=e),this.#t){let o=Os(e)||i.toHere(t.offset);this.#t[r]=o}return s}convert(e){let t;switch(this.mt){case xe.ARRAY:t=this.children;break;case xe.MAP:{let i=this.#n();if(this.#e.sortKeys){let s;for(let r of i){if(s&&this.#e.sortKeys(s,r)>=0)throw new Error(`Duplicate or out of order key: "0x${r[2]}"`);s=r}}else if(this.#e.rejectDuplicateKeys){let s=new Set;for(let[r,o,a]of i){let l=Fn(a);if(s.has(l))throw new Error(`Duplicate key: "0x${l}"`);s.add(l)}}t=this.#e.createObject(i,this.#e);break}case xe.BYTE_STRING:return rp(this.children);case xe.UTF8_STRING:{let i=this.children.join("");t=this.#e.boxed?Bs(i,e.toHere(this.offset)):i;break}case xe.TAG:t=this.children.decode(this.#e);break;default:throw new TypeError(`Invalid mt on convert: ${this.mt}`)}return this.#e.saveOriginal&&t&&typeof t=="object"&&Fs(t,e.toHere(this.offset)),t}#n(){let e=this.children,t=e.length;if(t%2)throw new Error("Missing map value");let i=new Array(t/2);if(this.#t)for(let s=0;s<t;s+=2)i[s>>1]=[e[s],e[s+1],this.#t[s]];else for(let s=0;s<t;s+=2)i[s>>1]=[e[s],e[s+1],_y];return i}};var yu="  ",xy=new TextEncoder,xl=class extends _n{close="";quote='"';get isEmptyStream(){return(this.mt===xe.UTF8_STRING||this.mt===xe.BYTE_STRING)&&this.count===0}};function Gs(n,e,t,i){let s="";if(e===ct.INDEFINITE)s+="_";else{if(i.diagnosticSizes===gr.NEVER)return"";{let r=i.diagnosticSizes===gr.ALWAYS;if(!r){let o=ct.ZERO;if(Object.is(t,-0))o=ct.TWO;else if(n===xe.POS_INT||n===xe.NEG_INT){let a=t<0,l=typeof t=="bigint"?1n:1,c=a?-t-l:t;c<=23?o=Number(c):c<=255?o=ct.ONE:c<=65535?o=ct.TWO:c<=4294967295?o=ct.FOUR:o=ct.EIGHT}else isFinite(t)?Math.fround(t)===t?dl(t)==null?o=ct.FOUR:o=ct.TWO:o=ct.EIGHT:o=ct.TWO;r=o!==e}r&&(s+="_",e<ct.ONE?s+="i":s+=String(e-24))}}return s}function xu(n,e){let t={..._n.defaultDecodeOptions,...e,ParentType:xl},i=new Ji(n,t),s,r,o="";for(let a of i){let[l,c,h]=a;switch(s&&(s.count>0&&h!==Kt.BREAK&&(s.mt===xe.MAP&&s.count%2?o+=": ":(o+=",",t.pretty||(o+=" "))),t.pretty&&(s.mt!==xe.MAP||s.count%2===0)&&(o+=`
${yu.repeat(s.depth+1)}`)),r=_n.create(a,s,t,i),l){case xe.POS_INT:case xe.NEG_INT:o+=String(h),o+=Gs(l,c,h,t);break;case xe.SIMPLE_FLOAT:if(h!==Kt.BREAK)if(typeof h=="number"){let d=Object.is(h,-0)?"-0.0":String(h);o+=d,isFinite(h)&&!/[.e]/.test(d)&&(o+=".0"),o+=Gs(l,c,h,t)}else h instanceof Ii?(o+="simple(",o+=String(h.value),o+=Gs(xe.POS_INT,c,h.value,t),o+=")"):o+=String(h);break;case xe.BYTE_STRING:h===1/0?(o+="(_ ",r.close=")",r.quote="'"):(o+="h'",o+=Fn(h),o+="'",o+=Gs(xe.POS_INT,c,h.length,t));break;case xe.UTF8_STRING:h===1/0?(o+="(_ ",r.close=")"):(o+=JSON.stringify(h),o+=Gs(xe.POS_INT,c,xy.encode(h).length,t));break;case xe.ARRAY:{o+="[";let d=Gs(xe.POS_INT,c,h,t);o+=d,d&&(o+=" "),t.pretty&&h?r.close=`
${yu.repeat(r.depth)}]`:r.close="]";break}case xe.MAP:{o+="{";let d=Gs(xe.POS_INT,c,h,t);o+=d,d&&(o+=" "),t.pretty&&h?r.close=`
${yu.repeat(r.depth)}}`:r.close="}";break}case xe.TAG:o+=String(h),o+=Gs(xe.POS_INT,c,h,t),o+="(",r.close=")";break}if(r===Kt.BREAK)if(s?.isStreaming)s.left=0;else throw new Error("Unexpected BREAK");else s&&(s.count++,s.left--);for(r instanceof xl&&(s=r);s?.done;){if(s.isEmptyStream)o=o.slice(0,-3),o+=`${s.quote}${s.quote}_`;else{if(s.mt===xe.MAP&&s.count%2!==0)throw new Error(`Odd streaming map size: ${s.count}`);o+=s.close}s=s.parent}}return o}var vy=new TextDecoder,oa=class extends _n{depth=0;leaf=!1;value;length;[Kt.ENCODED];constructor(e,t,i,s){super(e,t,i,s),this.parent?this.depth=this.parent.depth+1:this.depth=s.initialDepth,[,,this.value,,this.length]=e}numBytes(){switch(this.ai){case ct.ONE:return 1;case ct.TWO:return 2;case ct.FOUR:return 4;case ct.EIGHT:return 8}return 0}};function Rp(n){return n instanceof oa}function vl(n,e){return n===1/0?"Indefinite":e?`${n} ${e}${n!==1&&n!==1n?"s":""}`:String(n)}function ra(n){return"".padStart(n," ")}function Cp(n,e,t){let i="";i+=ra(n.depth*2);let s=Os(n);i+=Fn(s.subarray(0,1));let r=n.numBytes();r&&(i+=" ",i+=Fn(s.subarray(1,r+1))),i=i.padEnd(e.minCol+1," "),i+="-- ",t!==void 0&&(i+=ra(n.depth*2),t!==""&&(i+=`[${t}] `));let o=!1,[a]=n.children;switch(n.mt){case xe.POS_INT:i+=`Unsigned: ${a}`,typeof a=="bigint"&&(i+="n");break;case xe.NEG_INT:i+=`Negative: ${a}`,typeof a=="bigint"&&(i+="n");break;case xe.BYTE_STRING:i+=`Bytes (Length: ${vl(n.length)})`;break;case xe.UTF8_STRING:i+=`UTF8 (Length: ${vl(n.length)})`,n.length!==1/0&&(i+=`: ${JSON.stringify(a)}`);break;case xe.ARRAY:i+=`Array (Length: ${vl(n.value,"item")})`;break;case xe.MAP:i+=`Map (Length: ${vl(n.value,"pair")})`;break;case xe.TAG:{i+=`Tag #${n.value}`;let l=n.children,[c]=l.contents.children,h=new tt(l.tag,c);Fs(h,s);let d=h.comment(e,n.depth);d&&(i+=": ",i+=d),o||=h.noChildren;break}case xe.SIMPLE_FLOAT:a===Kt.BREAK?i+="BREAK":n.ai>ct.ONE?Object.is(a,-0)?i+="Float: -0":i+=`Float: ${a}`:(i+="Simple: ",a instanceof Ii?i+=a.value:i+=a);break}if(!o)if(n.leaf){if(i+=`
`,s.length>r+1){let l=ra((n.depth+1)*2),c=Ko(s);if(c?.length){c.sort((d,u)=>d[0]-u[0]||u[1]-d[1]);let h=0;for(let[d,u,m]of c)if(!(d<h)){if(h=d+u,m==="<<"){i+=ra(e.minCol+1),i+="--",i+=l,i+="<< ";let g=Jo(s,d,d+u),v=Ko(g);if(v){let f=v.findIndex(([p,x,A])=>p===0&&x===u&&A==="<<");f>=0&&v.splice(f,1)}i+=xu(g),i+=` >>
`,i+=bl(g,{initialDepth:n.depth+1,minCol:e.minCol,noPrefixHex:!0});continue}else m==="'"&&(i+=ra(e.minCol+1),i+="--",i+=l,i+="'",i+=vy.decode(s.subarray(d,d+u)),i+=`'
`);if(d>r)for(let g=d;g<d+u;g+=8){let v=Math.min(g+8,d+u);i+=l,i+=Fn(s.subarray(g,v)),i+=`
`}}}else for(let h=r+1;h<s.length;h+=8)i+=l,i+=Fn(s.subarray(h,h+8)),i+=`
`}}else{i+=`
`;let l=0;for(let c of n.children){if(Rp(c)){let h=String(l);n.mt===xe.MAP?h=l%2?`val ${(l-1)/2}`:`key ${l/2}`:n.mt===xe.TAG&&(h=""),i+=Cp(c,e,h)}l++}}return i}var by={..._n.defaultDecodeOptions,initialDepth:0,noPrefixHex:!1,minCol:0};function bl(n,e){let t={...by,...e,ParentType:oa,saveOriginal:!0},i=new Ji(n,t),s,r;for(let a of i){if(r=_n.create(a,s,t,i),a[2]===Kt.BREAK)if(s?.isStreaming)s.left=1;else throw new Error("Unexpected BREAK");if(!Rp(r)){let h=new oa(a,0,s,t);h.leaf=!0,h.children.push(r),Fs(h,i.toHere(a[3])),r=h}let l=(r.depth+1)*2,c=r.numBytes();for(c&&(l+=1,l+=c*2),t.minCol=Math.max(t.minCol,l),s&&s.push(r,i,a[3]),s=r;s?.done;)r=s,r.leaf||Fs(r,i.toHere(r.offset)),{parent:s}=s}e&&(e.minCol=t.minCol);let o=t.noPrefixHex?"":`0x${Fn(i.toHere(0))}
`;return o+=Cp(r,t),o}var Ip=!ap();function wl(n){if(typeof n=="object"&&n){if(n.constructor!==Number)throw new Error(`Expected number: ${n}`)}else if(typeof n!="number")throw new Error(`Expected number: ${n}`)}function fs(n){if(typeof n=="object"&&n){if(n.constructor!==String)throw new Error(`Expected string: ${n}`)}else if(typeof n!="string")throw new Error(`Expected string: ${n}`)}function ps(n){if(!(n instanceof Uint8Array))throw new Error(`Expected Uint8Array: ${n}`)}function Op(n){if(!Array.isArray(n))throw new Error(`Expected Array: ${n}`)}nn(Map,(n,e,t)=>{let i=[...n.entries()].map(s=>[s[0],s[1],zs(s[0],t)]);if(t.rejectDuplicateKeys){let s=new Set;for(let[r,o,a]of i){let l=Fn(a);if(s.has(l))throw new Error(`Duplicate map key: 0x${l}`);s.add(l)}}t.sortKeys&&i.sort(t.sortKeys),yl(n,n.size,xe.MAP,e,t);for(let[s,r,o]of i)e.write(o),ks(r,e,t)});function vu(n){return fs(n.contents),new Date(n.contents)}vu.comment=n=>{fs(n.contents);let e=new Date(n.contents);return`(String ${n.tag===Mt.DATE_FULL?"Full ":""}Date) ${e.toISOString()}`},tt.registerDecoder(Mt.DATE_STRING,vu),tt.registerDecoder(Mt.DATE_FULL,vu);function Pp(n){return wl(n.contents),new Date(n.contents*1e3)}Pp.comment=n=>(wl(n.contents),`(Epoch Date) ${new Date(n.contents*1e3).toISOString()}`),tt.registerDecoder(Mt.DATE_EPOCH,Pp);var Mu=1e3*60*60*24;function Lp(n){return wl(n.contents),new Date(n.contents*Mu)}Lp.comment=n=>(wl(n.contents),`(Epoch Date) ${new Date(n.contents*Mu).toISOString()}`),tt.registerDecoder(Mt.DATE_EPOCH_DAYS,Lp),nn(Date,(n,e,t)=>{switch(t.dateTag){case Mt.DATE_EPOCH:return[t.dateTag,n.valueOf()/1e3];case Mt.DATE_STRING:return[t.dateTag,n.toISOString().replace(/\.000Z$/,"Z")];case Mt.DATE_EPOCH_DAYS:return[t.dateTag,Math.floor(n.valueOf()/Mu)];case Mt.DATE_FULL:return[t.dateTag,n.toISOString().split("T")[0]];default:throw new Error(`Unsupported date tag: ${t.dateTag}`)}});function Ml(n,e,t){if(ps(e.contents),t.rejectBigInts)throw new Error(`Decoding unwanted big integer: ${e}(h'${Fn(e.contents)}')`);if(t.requirePreferred&&e.contents[0]===0)throw new Error(`Decoding overly-large bigint: ${e.tag}(h'${Fn(e.contents)})`);let i=e.contents.reduce((r,o)=>r<<8n|BigInt(o),0n);n&&(i=-1n-i);let s=i>=Number.MIN_SAFE_INTEGER&&i<=Number.MAX_SAFE_INTEGER;if(t.requirePreferred&&s)throw new Error(`Decoding bigint that could have been int: ${i}n`);return t.collapseBigInts&&s&&(i=Number(i)),t.boxed?Bs(i,e.contents):i}var Np=Ml.bind(null,!1),Dp=Ml.bind(null,!0);Np.comment=(n,e)=>`(Positive BigInt) ${Ml(!1,n,e)}n`,Dp.comment=(n,e)=>`(Negative BigInt) ${Ml(!0,n,e)}n`,tt.registerDecoder(Mt.POS_BIGINT,Np),tt.registerDecoder(Mt.NEG_BIGINT,Dp);function bu(n,e){return ps(n.contents),n}bu.comment=(n,e,t)=>{ps(n.contents);let i={...e,initialDepth:t+2,noPrefixHex:!0},s=Os(n),r=2**((s[0]&31)-24)+1,o=s[r]&31,a=Fn(s.subarray(r,++r));o>=24&&(a+=" ",a+=Fn(s.subarray(r,r+2**(o-24)))),i.minCol=Math.max(i.minCol,(t+1)*2+a.length);let l=bl(n.contents,i),c=`Embedded CBOR
`;return c+=`${"".padStart((t+1)*2," ")}${a}`.padEnd(i.minCol+1," "),c+=`-- Bytes (Length: ${n.contents.length})
`,c+=l,c},bu.noChildren=!0,tt.registerDecoder(Mt.CBOR,bu),tt.registerDecoder(Mt.URI,n=>(fs(n.contents),new URL(n.contents)),"URI"),nn(URL,n=>[Mt.URI,n.toString()]),tt.registerDecoder(Mt.BASE64URL,n=>(fs(n.contents),op(n.contents)),"Base64url-encoded"),tt.registerDecoder(Mt.BASE64,n=>(fs(n.contents),jo(n.contents)),"Base64-encoded"),tt.registerDecoder(35,n=>(fs(n.contents),new RegExp(n.contents)),"RegExp"),tt.registerDecoder(21065,n=>{fs(n.contents);let e=`^(?:${n.contents})$`;return new RegExp(e,"u")},"I-RegExp"),tt.registerDecoder(Mt.REGEXP,n=>{if(Op(n.contents),n.contents.length<1||n.contents.length>2)throw new Error(`Invalid RegExp Array: ${n.contents}`);return new RegExp(n.contents[0],n.contents[1])},"RegExp"),nn(RegExp,n=>[Mt.REGEXP,[n.source,n.flags]]),tt.registerDecoder(64,n=>(ps(n.contents),n.contents),"uint8 Typed Array");function kn(n,e,t){ps(n.contents);let i=n.contents.length;if(i%e.BYTES_PER_ELEMENT!==0)throw new Error(`Number of bytes must be divisible by ${e.BYTES_PER_ELEMENT}, got: ${i}`);i/=e.BYTES_PER_ELEMENT;let s=new e(i),r=new DataView(n.contents.buffer,n.contents.byteOffset,n.contents.byteLength),o=r[`get${e.name.replace(/Array/,"")}`].bind(r);for(let a=0;a<i;a++)s[a]=o(a*e.BYTES_PER_ELEMENT,t);return s}function Hs(n,e,t,i,s){let r=s.forceEndian??Ip;if(mr(r?e:t,n,s),Qn(i.byteLength,n,xe.BYTE_STRING),Ip===r)n.write(new Uint8Array(i.buffer,i.byteOffset,i.byteLength));else{let o=`write${i.constructor.name.replace(/Array/,"")}`,a=n[o].bind(n);for(let l of i)a(l,r)}}tt.registerDecoder(65,n=>kn(n,Uint16Array,!1),"uint16, big endian, Typed Array"),tt.registerDecoder(66,n=>kn(n,Uint32Array,!1),"uint32, big endian, Typed Array"),tt.registerDecoder(67,n=>kn(n,BigUint64Array,!1),"uint64, big endian, Typed Array"),tt.registerDecoder(68,n=>(ps(n.contents),new Uint8ClampedArray(n.contents)),"uint8 Typed Array, clamped arithmetic"),nn(Uint8ClampedArray,n=>[68,new Uint8Array(n.buffer,n.byteOffset,n.byteLength)]),tt.registerDecoder(69,n=>kn(n,Uint16Array,!0),"uint16, little endian, Typed Array"),nn(Uint16Array,(n,e,t)=>Hs(e,69,65,n,t)),tt.registerDecoder(70,n=>kn(n,Uint32Array,!0),"uint32, little endian, Typed Array"),nn(Uint32Array,(n,e,t)=>Hs(e,70,66,n,t)),tt.registerDecoder(71,n=>kn(n,BigUint64Array,!0),"uint64, little endian, Typed Array"),nn(BigUint64Array,(n,e,t)=>Hs(e,71,67,n,t)),tt.registerDecoder(72,n=>(ps(n.contents),new Int8Array(n.contents)),"sint8 Typed Array"),nn(Int8Array,n=>[72,new Uint8Array(n.buffer,n.byteOffset,n.byteLength)]),tt.registerDecoder(73,n=>kn(n,Int16Array,!1),"sint16, big endian, Typed Array"),tt.registerDecoder(74,n=>kn(n,Int32Array,!1),"sint32, big endian, Typed Array"),tt.registerDecoder(75,n=>kn(n,BigInt64Array,!1),"sint64, big endian, Typed Array"),tt.registerDecoder(77,n=>kn(n,Int16Array,!0),"sint16, little endian, Typed Array"),nn(Int16Array,(n,e,t)=>Hs(e,77,73,n,t)),tt.registerDecoder(78,n=>kn(n,Int32Array,!0),"sint32, little endian, Typed Array"),nn(Int32Array,(n,e,t)=>Hs(e,78,74,n,t)),tt.registerDecoder(79,n=>kn(n,BigInt64Array,!0),"sint64, little endian, Typed Array"),nn(BigInt64Array,(n,e,t)=>Hs(e,79,75,n,t)),tt.registerDecoder(81,n=>kn(n,Float32Array,!1),"IEEE 754 binary32, big endian, Typed Array"),tt.registerDecoder(82,n=>kn(n,Float64Array,!1),"IEEE 754 binary64, big endian, Typed Array"),tt.registerDecoder(85,n=>kn(n,Float32Array,!0),"IEEE 754 binary32, little endian, Typed Array"),nn(Float32Array,(n,e,t)=>Hs(e,85,81,n,t)),tt.registerDecoder(86,n=>kn(n,Float64Array,!0),"IEEE 754 binary64, big endian, Typed Array"),nn(Float64Array,(n,e,t)=>Hs(e,86,82,n,t)),tt.registerDecoder(Mt.SET,(n,e)=>{if(Op(n.contents),e.sortKeys){let t=_n.decodeToEncodeOpts(e),i=null;for(let s of n.contents){let r=[s,void 0,zs(s,t)];if(i&&e.sortKeys(i,r)>=0)throw new Error(`Set items out of order in tag #${Mt.SET}`);i=r}}return new Set(n.contents)},"Set"),nn(Set,(n,e,t)=>{let i=[...n];if(t.sortKeys){let s=i.map(r=>[r,void 0,zs(r,t)]);s.sort(t.sortKeys),i=s.map(([r])=>r)}return[Mt.SET,i]}),tt.registerDecoder(Mt.JSON,n=>(fs(n.contents),JSON.parse(n.contents)),"JSON-encoded");function Up(n){return ps(n.contents),new pr().decode(n.contents)}Up.comment=n=>{ps(n.contents);let e=new pr;return`(WTF8 string): ${JSON.stringify(e.decode(n.contents))}`},tt.registerDecoder(Mt.WTF8,Up),tt.registerDecoder(Mt.SELF_DESCRIBED,n=>n.contents,"Self-Described"),tt.registerDecoder(Mt.INVALID_16,()=>{throw new Error(`Tag always invalid: ${Mt.INVALID_16}`)},"Invalid"),tt.registerDecoder(Mt.INVALID_32,()=>{throw new Error(`Tag always invalid: ${Mt.INVALID_32}`)},"Invalid"),tt.registerDecoder(Mt.INVALID_64,()=>{throw new Error(`Tag always invalid: ${Mt.INVALID_64}`)},"Invalid"),tt.registerDecoder(Mt.SYMBOL,n=>{let e=n.contents;if(Array.isArray(n.contents)){if(n.contents.length!==1)throw new Error(`Expected Array of size 1: ${n.contents}`);[e]=n.contents}if(fs(e),!e.length)throw new Error(`Expected non-empty string: ${n.contents}`);return Symbol.for(e)},"Symbol");function Su(n){throw new Error(`Encoding ${n.constructor.name} intentionally unimplmented.  It is not concrete enough to interoperate.  Convert to Uint8Array first.`)}nn(ArrayBuffer,Su),nn(DataView,Su),typeof SharedArrayBuffer<"u"&&nn(SharedArrayBuffer,Su);function Sl(n){return[NaN,n.valueOf()]}nn(Boolean,Sl),nn(Number,Sl),nn(String,Sl),nn(BigInt,Sl);function Sy(n){let e={..._n.defaultDecodeOptions};if(n.dcbor?Object.assign(e,_n.dcborDecodeOptions):n.cde&&Object.assign(e,_n.cdeDecodeOptions),Object.assign(e,n),Object.hasOwn(e,"rejectLongNumbers"))throw new TypeError("rejectLongNumbers has changed to requirePreferred");return e.boxed&&(e.saveOriginal=!0),e}var wu=class{parent=void 0;ret=void 0;step(e,t,i){if(this.ret=_n.create(e,this.parent,t,i),e[2]===Kt.BREAK)if(this.parent?.isStreaming)this.parent.left=0;else throw new Error("Unexpected BREAK");else this.parent&&this.parent.push(this.ret,i,e[3]);for(this.ret instanceof _n&&(this.parent=this.ret);this.parent?.done;){this.ret=this.parent.convert(i);let s=this.parent.parent;s?.replaceLast(this.ret,this.parent,i),this.parent=s}}};function Eu(n,e={}){let t=Sy(e),i=new Ji(n,t),s=new wu;for(let r of i)s.step(r,t,i);return s.ret}var{cdeDecodeOptions:IA,dcborDecodeOptions:PA,defaultDecodeOptions:LA}=_n;function My(n){let e=n instanceof Uint8Array?n:new Uint8Array(n);return Eu(e)}var Vs=class extends Error{},El=class{constructor(e){this.url=e;this.connect()}url;ws=null;subs=new Map;pending=new Map;goals=new Map;statusWaiters=new Map;nextId=1;closed=!1;retryMs=500;onState=()=>{};framesIn=0;bytesIn=0;connect(){this.onState("connecting");let e=new WebSocket(this.url);e.binaryType="arraybuffer",this.ws=e,e.onopen=()=>{this.retryMs=500,this.onState("open");for(let t of this.subs.values())this.sendSubscribe(t)},e.onmessage=t=>this.onFrame(t.data),e.onclose=t=>{this.onState("closed",t.reason||`code ${t.code}`);for(let[i,s]of this.pending)clearTimeout(s.timer),s.reject(new Error("connection to the hub lost")),this.pending.delete(i);this.closed||(setTimeout(()=>this.connect(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))}}close(){this.closed=!0,this.onState=()=>{},this.ws?.close()}send(e){this.ws?.readyState===WebSocket.OPEN&&this.ws.send(JSON.stringify(e))}onFrame(e){let t=performance.now();this.framesIn++;let i,s=typeof e=="string"?e.length:e.byteLength;try{typeof e=="string"?(this.bytesIn+=e.length,i=JSON.parse(e)):(this.bytesIn+=e.byteLength,i=My(e)),vt.busyMs.decode+=performance.now()-t}catch(r){console.warn("undecodable frame from the hub",r);return}switch(i.op){case"publish":{let r=String(i.topic);for(let o of this.subs.values())if(o.topic===r||o.opts.regex&&new RegExp(`^(?:${o.topic})$`).test(r))for(let a of o.handlers)try{a(i.msg,r,t,s)}catch(l){console.error(`handler for ${r} failed`,l)}break}case"service_response":{let r=this.pending.get(String(i.id));if(!r)break;this.pending.delete(String(i.id)),clearTimeout(r.timer),i.result===!1?r.reject(new Vs(typeof i.values=="string"?i.values:JSON.stringify(i.values))):r.resolve(i.values);break}case"action_feedback":{this.goals.get(String(i.id))?.onFeedback(i.values);break}case"action_result":{let r=this.goals.get(String(i.id));if(!r)break;this.goals.delete(String(i.id)),r.done.resolve({status:i.status,values:i.values,result:i.result});break}case"status":{let r=i.id===void 0?void 0:String(i.id);if(i.level==="error"&&r){let o=this.pending.get(r);o&&(this.pending.delete(r),clearTimeout(o.timer),o.reject(new Vs(String(i.msg))));let a=this.goals.get(r);a&&(this.goals.delete(r),a.done.reject(new Vs(String(i.msg)))),this.statusWaiters.get(r)?.(String(i.msg))}i.level==="error"&&!r&&console.warn("hub:",i.msg);break}}}sendSubscribe(e){this.send({op:"subscribe",id:`sub:${e.topic}`,topic:e.topic,type:e.opts.type,compression:e.opts.compression??"cbor",queue_length:e.opts.queue_length??1,throttle_rate:e.opts.throttle_rate??0,regex:e.opts.regex||void 0})}subscribe(e,t,i={}){let s=this.subs.get(e);return s||(s={topic:e,opts:i,handlers:new Set},this.subs.set(e,s),this.sendSubscribe(s)),s.handlers.add(t),()=>{let r=this.subs.get(e);r&&(r.handlers.delete(t),r.handlers.size===0&&(this.subs.delete(e),this.send({op:"unsubscribe",id:`sub:${e}`,topic:e})))}}call(e,t={},i=10){let s=`call:${this.nextId++}`;return new Promise((r,o)=>{let a=window.setTimeout(()=>{this.pending.delete(s),o(new Error(`${e}: no answer within ${i+2} s`))},(i+2)*1e3);this.pending.set(s,{resolve:r,reject:o,timer:a}),this.send({op:"call_service",id:s,service:e,args:t,timeout:i})})}advertise(e,t,i=1500){let s=`adv:${e}:${this.nextId++}`;return new Promise(r=>{let o=window.setTimeout(()=>{this.statusWaiters.delete(s),r(null)},i);this.statusWaiters.set(s,a=>{clearTimeout(o),this.statusWaiters.delete(s),r(a)}),this.send({op:"advertise",id:s,topic:e,type:t})})}unadvertise(e){this.send({op:"unadvertise",topic:e})}publish(e,t,i){let s=`pub:${e}:${this.nextId++}`;i&&(this.statusWaiters.set(s,r=>{this.statusWaiters.delete(s),i(r)}),setTimeout(()=>this.statusWaiters.delete(s),5e3)),this.send({op:"publish",id:s,topic:e,msg:t})}sendGoal(e,t,i,s){let r=`goal:${this.nextId++}`,o=new Promise((a,l)=>{this.goals.set(r,{onFeedback:s,done:{resolve:a,reject:l,timer:0}})});return this.send({op:"send_action_goal",id:r,action:e,action_type:t,args:i,feedback:!0}),{id:r,result:o,cancel:()=>this.send({op:"cancel_action_goal",id:r,action:e})}}};function te(n,e="",t){let i=document.createElement(n);return e&&(i.className=e),t!==void 0&&(i.textContent=t),i}function Nt(n,e=1){return n==null||!Number.isFinite(n)?"–":Math.abs(n)>=100?n.toFixed(0):n.toFixed(e)}function zn(n){if(n==null||!Number.isFinite(n)||n<=0)return"–";let e=["B/s","kB/s","MB/s","GB/s"],t=n,i=0;for(;t>=1e3&&i<e.length-1;)t/=1e3,i++;return`${t.toFixed(t>=100?0:1)} ${e[i]}`}function _r(n){if(!n)return"never";let e=Math.max(0,(Date.now()-n)/1e3);return e<2?"just now":e<90?`${e.toFixed(0)} s ago`:e<5400?`${(e/60).toFixed(0)} min ago`:new Date(n).toLocaleString()}function In(n,e="",t){let i=te("button",e,n);return t&&i.addEventListener("click",t),i}function Jr(n,e="",t=0){if(n!==null&&typeof n=="object"){let s=te("details");t<2&&(s.open=!0);let r=Object.entries(n);s.appendChild(te("summary","",`${e}${e?": ":""}${Array.isArray(n)?`[${r.length}]`:`{${r.length}}`}`));for(let[o,a]of r)s.appendChild(Jr(a,o,t+1));return s}let i=te("div","leaf");return i.appendChild(te("span","key",e?`${e}: `:"")),i.appendChild(te("span",`val ${typeof n}`,JSON.stringify(n)??String(n))),i}function Fp(n){n.innerHTML="";let e=te("div","admin"),t=te("section","panel wide");t.appendChild(te("h2","","Audit log"));let i=te("form","filters"),s={};for(let[x,A]of[["principal","user:alice"],["action","publish"],["name_regex","/robot1/.*"]]){let b=te("input");b.name=x,b.placeholder=`${x} e.g. ${A}`,s[x]=b,i.appendChild(b)}let r=te("select");r.name="allowed";for(let[x,A]of[["","allowed and denied"],["true","allowed only"],["false","denied only"]])r.appendChild(new Option(A,x));s.allowed=r,i.appendChild(r);let o=In("Filter","primary");o.type="submit",i.appendChild(o);let a=te("table","audit"),l=te("div","pager"),c=In("Next page →"),h=In("⇤ First page"),d=te("span","muted");l.append(h,c,d),t.append(i,a,l);let u=te("section","panel wide");u.appendChild(te("h2","","Access rules"));let m=te("div");u.appendChild(m),e.append(t,u),n.appendChild(e);let g=50,v=[null],f=0;async function p(){let x=new URLSearchParams({limit:String(g)});for(let[b,C]of Object.entries(s))C.value&&x.set(b,C.value);let A=v[f];A!=null&&x.set("cursor",typeof A=="string"?A:JSON.stringify(A));try{let b=await gn(`/api/v1/audit?${x}`);a.innerHTML="<thead><tr><th>time</th><th>principal</th><th>client</th><th>action</th><th>name</th><th>size</th><th>allowed</th><th>detail</th></tr></thead>";let C=te("tbody");for(let w of b.records){let _=te("tr",w.allowed?"":"denied"),M=w.at?.secs!=null?w.at.secs*1e3:typeof w.at=="number"?w.at>1e12?w.at:w.at*1e3:NaN;for(let U of[Number.isFinite(M)?new Date(M).toLocaleString():JSON.stringify(w.at),w.principal,w.client_ip,w.action,w.name,w.size??"",w.allowed?"yes":"no",w.detail??""])_.appendChild(te("td","",String(U)));C.appendChild(_)}a.appendChild(C),v=v.slice(0,f+1),b.next!=null&&v.push(b.next),c.disabled=b.next==null,h.disabled=f===0,d.textContent=`page ${f+1} · ${b.records.length} records`}catch(b){a.replaceChildren(te("caption","why",`The hub refused the audit log: ${b.message}`)),c.disabled=h.disabled=!0}}return i.addEventListener("submit",x=>{x.preventDefault(),v=[null],f=0,p()}),c.addEventListener("click",()=>{f++,p()}),h.addEventListener("click",()=>{f=0,p()}),p(),gn("/api/v1/rules").then(x=>{let A=te("table","rules");A.innerHTML="<thead><tr><th>id</th><th>subject</th><th>names</th><th>ops</th><th>effect</th><th>comment</th></tr></thead>";let b=te("tbody");for(let C of x.rules){let w=C.rule??C,_=te("tr"),M=w.subject&&typeof w.subject=="object"?Object.entries(w.subject).map(([U,L])=>`${U}:${L}`).join(" "):w.subject;for(let U of[C.id??"",M,w.names,Array.isArray(w.ops)?w.ops.join(", "):w.ops,w.effect??"allow",w.comment??""])_.appendChild(te("td","",typeof U=="string"||typeof U=="number"?String(U):JSON.stringify(U)));b.appendChild(_)}A.appendChild(b),m.replaceChildren(x.rules.length?A:te("p","muted","No rules: only the built-in defaults apply (admin group, robots' own namespaces, anonymous read where enabled)."))},x=>m.replaceChildren(te("p","why",`The hub refused the rules: ${x.message}`))),()=>{}}function aa(n){let e=["B","kB","MB","GB","TB"],t=n,i=0;for(;t>=1e3&&i<e.length-1;)t/=1e3,i++;return`${t.toFixed(t>=100||i===0?0:1)} ${e[i]}`}function Bp(n){return n.split(/\s+/).filter(Boolean)}function wy(n){let e=n.range,t=e.last_s!=null?`last ${e.last_s} s`:e.from_ns!=null?`from ${new Date(e.from_ns/1e6).toLocaleString()}${e.to_ns!=null?` to ${new Date(e.to_ns/1e6).toLocaleString()}`:""}`:"",i=e.topics.length?e.topics.join(" "):"every topic it keeps";return`black box of ${n.robot}${t?`, ${t}`:""}: ${i}`}function Ey(n){let e=te("td","",n.error?`${n.state}: ${n.error}`:n.state),t=n.blackbox;if(n.state!=="fetching"||!t)return e;if(t.size!=null){let i=t.size>0?Math.floor(t.received*100/t.size):100,s=te("progress");s.max=Math.max(t.size,1),s.value=Math.min(t.received,s.max),e.append(s,te("div","",`${i}% · ${aa(t.received)} of ${aa(t.size)}`))}else t.received>0&&e.append(te("div","",`${aa(t.received)} received`));return t.waiting&&e.append(te("div","why",t.waiting)),t.resumed>0&&e.append(te("div","muted",`resumed ${t.resumed}×`)),e}function kp(n){n.innerHTML="";let e=te("section","panel wide");e.appendChild(te("h2","","Recordings"));let t=te("form","filters");t.id="record-form";let i=te("input");i.name="topics",i.placeholder="topics, e.g. /robot1/.* /robot2/scan",i.size=40;let s=te("input");s.name="duration",s.placeholder="duration in s (empty: until stopped)";let r=In("Start recording","primary");r.type="submit";let o=te("span","muted");o.id="record-status",t.append(i,s,r,o);let a=te("form","filters");a.id="blackbox-form";let l=te("select");l.name="robot",l.title="the robot whose black box to read (an offline one is waited for)";let c=te("input");c.name="last_s",c.type="number",c.step="any",c.value="60",c.style.width="6em";let h=te("label","muted","last ");h.append(c," s");let d=te("input");d.name="topics",d.placeholder="the robot's own topics, e.g. /scan /odom (empty: all)",d.size=40;let u=te("input");u.name="name",u.placeholder="name (optional)";let m=In("Fetch black box","primary");m.type="submit";let g=te("span","muted");g.id="blackbox-status",a.append(l,h,d,u,m,g);let v=te("table","recordings");v.id="recordings",e.append(t,a,v),n.appendChild(e);async function f(){try{let _=await gn("/api/v1/recordings");v.innerHTML="<thead><tr><th>id</th><th>state</th><th>topics</th><th>started</th><th>by</th><th>messages</th><th>size</th><th>dropped</th><th>files</th><th></th></tr></thead>";let M=te("tbody");for(let U of _.recordings){let L=te("tr",U.blackbox?`${U.state} blackbox`:U.state);L.dataset.id=U.id,L.append(te("td","",U.id),Ey(U)),L.append(te("td","",U.blackbox?wy(U.blackbox):U.spec.topics.join(" ")));for(let F of[_r(U.started_at_ms),U.started_by,String(U.messages),aa(U.bytes),String(U.dropped)])L.appendChild(te("td","",F));let R=te("td");for(let F of U.files){let P=te("a","",F.name),B=Si.token()?`?token=${encodeURIComponent(Si.token())}`:"";P.href=`/api/v1/recordings/${encodeURIComponent(U.id)}/files/${encodeURIComponent(F.name)}${B}`,P.download=F.name,P.title=`${F.messages} messages, ${aa(F.bytes)}`,R.append(P," ")}L.appendChild(R);let z=te("td");U.state==="recording"||U.state==="fetching"?z.appendChild(In("Stop","",()=>b(`/api/v1/recordings/${encodeURIComponent(U.id)}/stop`,"POST"))):z.appendChild(In("Remove","",()=>confirm(`Delete ${U.id} and its files?`)&&b(`/api/v1/recordings/${encodeURIComponent(U.id)}`,"DELETE"))),L.appendChild(z),M.appendChild(L)}v.appendChild(M),_.recordings.length||v.appendChild(te("caption","muted","No recordings yet."))}catch(_){v.replaceChildren(te("caption","why",`The hub refused the recordings: ${_.message}`))}}let p="";async function x(){let _;try{({robots:_}=await gn("/api/v1/robots"))}catch(R){p="";let z=te("option","",`cannot list robots: ${R.message}`);z.value="",l.replaceChildren(z);return}_.sort((R,z)=>R.name.localeCompare(z.name,void 0,{numeric:!0}));let M=_.map(R=>R.online?R.name:`${R.name} (offline)`);if(M.join(`
`)===p&&_.length)return;p=M.join(`
`);let U=l.value,L=_.map((R,z)=>{let F=te("option","",M[z]);return F.value=R.name,F});if(!L.length){let R=te("option","","no robots known");R.value="",L.push(R)}l.replaceChildren(...L),_.some(R=>R.name===U)&&(l.value=U)}async function A(_,M,U,L,R){try{let z=L===void 0?{method:U}:{method:U,body:JSON.stringify(L)},F=await gn(M,z);_.textContent=R?R(F):""}catch(z){_.textContent=`refused: ${z.message}`}f()}let b=(_,M)=>A(o,_,M);t.addEventListener("submit",_=>{_.preventDefault();let M={topics:Bp(i.value)};s.value.trim()&&(M.duration_s=Number(s.value)),A(o,"/api/v1/recordings","POST",M,U=>`started ${U.id}`)}),a.addEventListener("submit",_=>{_.preventDefault();let M={robot:l.value,topics:Bp(d.value)};c.value.trim()&&(M.last_s=Number(c.value)),u.value.trim()&&(M.name=u.value.trim()),A(g,"/api/v1/recordings/blackbox","POST",M,U=>`fetching ${U.id}`)}),f(),x();let C=setInterval(f,2e3),w=setInterval(x,1e4);return()=>{clearInterval(C),clearInterval(w)}}function Rl(n){if(n instanceof Uint8Array)return n;if(ArrayBuffer.isView(n))return new Uint8Array(n.buffer,n.byteOffset,n.byteLength);if(typeof n=="string"){let e=atob(n),t=new Uint8Array(e.length);for(let i=0;i<e.length;i++)t[i]=e.charCodeAt(i);return t}return Array.isArray(n)?Uint8Array.from(n):new Uint8Array(0)}function Cl(n){let e=n?.stamp;if(!e)return null;let t=e.sec??e.secs,i=e.nanosec??e.nsecs??0;return typeof t=="number"?t*1e3+i/1e6:null}function Tu(n){return Math.atan2(2*(n.w*n.z+n.x*n.y),1-2*(n.y*n.y+n.z*n.z))}function Il(n){let e=n?.pose;return e?.pose&&(e=e.pose),!e?.position||!e?.orientation?null:{x:e.position.x,y:e.position.y,yaw:Tu(e.orientation)}}function Gp(n){let e=n.ranges??[],t=new Float32Array(e.length*2),i=0;for(let s=0;s<e.length;s++){let r=e[s];if(!(r>=n.range_min&&r<=n.range_max))continue;let o=n.angle_min+s*n.angle_increment;t[i++]=r*Math.cos(o),t[i++]=r*Math.sin(o)}return t.subarray(0,i)}var Tl={1:[1,(n,e)=>n.getInt8(e)],2:[1,(n,e)=>n.getUint8(e)],3:[2,(n,e,t)=>n.getInt16(e,t)],4:[2,(n,e,t)=>n.getUint16(e,t)],5:[4,(n,e,t)=>n.getInt32(e,t)],6:[4,(n,e,t)=>n.getUint32(e,t)],7:[4,(n,e,t)=>n.getFloat32(e,t)],8:[8,(n,e,t)=>n.getFloat64(e,t)]};function Hp(n,e){let t=Rl(n.data),i=(n.width??0)*(n.height??1),s=n.point_step,r=!n.is_bigendian,o=_=>n.fields.find(M=>M.name===_),a=o("x"),l=o("y"),c=o("z"),h=o("intensity");if(!a||!l||!c||!s)throw new Error("PointCloud2 without x, y, z fields");let d=e&&e.positions.length>=i*3?e.positions:new Float32Array(i*3),u=e&&e.intensity.length>=i?e.intensity:new Float32Array(i),m=new DataView(t.buffer,t.byteOffset,t.byteLength),g=r&&a.datatype===7&&l.datatype===7&&c.datatype===7,v=Tl[a.datatype][1],f=Tl[l.datatype][1],p=Tl[c.datatype][1],x=h?Tl[h.datatype]?.[1]:void 0,A=n.height??1,b=n.width??0,C=n.row_step||b*s,w=0;for(let _=0;_<A;_++)for(let M=0;M<b;M++){let U=_*C+M*s;if(U+s>t.byteLength)break;let L=g?m.getFloat32(U+a.offset,!0):v(m,U+a.offset,r),R=g?m.getFloat32(U+l.offset,!0):f(m,U+l.offset,r),z=g?m.getFloat32(U+c.offset,!0):p(m,U+c.offset,r);!Number.isFinite(L)||!Number.isFinite(R)||!Number.isFinite(z)||(d[w*3]=L,d[w*3+1]=R,d[w*3+2]=z,u[w]=x?x(m,U+h.offset,r):NaN,w++)}return{positions:d,intensity:u,count:w}}function Vp(n){return n.length>3&&n[0]===255&&n[1]===216&&n[2]===255?"jpeg":n.length>8&&n[0]===137&&n[1]===80&&n[2]===78&&n[3]===71?"png":"unknown"}function Al(n,e=64){if(n instanceof Uint8Array)return`<${n.length} bytes>`;if(ArrayBuffer.isView(n)){let t=Array.from(n).slice(0,e),i=n.length;return i>e?[...t,`… ${i-e} more (${n.constructor.name})`]:t}if(Array.isArray(n)){let t=n.slice(0,e).map(i=>Al(i,e));return n.length>e?[...t,`… ${n.length-e} more`]:t}if(n&&typeof n=="object"){let t={};for(let[i,s]of Object.entries(n))t[i]=Al(s,e);return t}return n}var zp={bool:!1,string:"",float32:0,float64:0,int8:0,uint8:0,int16:0,uint16:0,int32:0,uint32:0,int64:0,uint64:0,byte:0,char:0,time:{sec:0,nanosec:0},duration:{sec:0,nanosec:0}};function Wp(n,e){let t=e?n.find(s=>s.type===e):n[0],i=(s,r)=>{let o={};return!s||r>16||s.fieldnames.forEach((a,l)=>{let c=s.fieldtypes[l],h=s.fieldarraylen?.[l]??-1,d=c in zp?zp[c]:i(n.find(u=>u.type===c),r+1);o[a]=h===-1?d:h===0?[]:Array.from({length:h},()=>d)}),o};return i(t,0)}var Ty=["ARROW","CUBE","SPHERE","CYLINDER","LINE_STRIP","LINE_LIST","CUBE_LIST","SPHERE_LIST","POINTS","TEXT_VIEW_FACING","MESH_RESOURCE","TRIANGLE_LIST"],Xp=0,Ay=2,Ry=3,$p=(n,e)=>`${n}\0${e}`;function Cy(n){return n?(n.sec??n.secs??0)*1e3+(n.nanosec??n.nsecs??0)/1e6:0}var Pl=class{markers=new Map;apply(e,t){if(Array.isArray(e?.markers))for(let i of e.markers)this.applyOne(i,t);else e&&typeof e=="object"&&this.applyOne(e,t)}applyOne(e,t){let i=e.ns??"",s=e.id??0,r=e.action??Xp;if(r===Ry)if(!i)this.markers.clear();else for(let[o,a]of this.markers)(a.msg.ns??"")===i&&this.markers.delete(o);else if(r===Ay)this.markers.delete($p(i,s));else if(r===Xp||r===1){let o=Cy(e.lifetime);this.markers.set($p(i,s),{msg:e,expires:o>0?t+o:1/0})}}live(e){let t=[];for(let[i,s]of this.markers)s.expires<=e?this.markers.delete(i):t.push(s);return t}nextExpiry(){let e=1/0;for(let t of this.markers.values())e=Math.min(e,t.expires);return e}};function qp(n,e){let t=n??e??{},i=s=>Math.round(Math.min(1,Math.max(0,s??0))*255);return`rgba(${i(t.r)},${i(t.g)},${i(t.b)},${Math.min(1,Math.max(0,t.a??1))})`}function Yp(n){let e=n.pose?.position??{},t=n.pose?.orientation,i=e.x??0,s=e.y??0,r=t?Tu(t):0,o=Math.cos(r),a=Math.sin(r),l=n.scale?.x??0,c=n.scale?.y??0,h=n.scale?.z??0,d=qp(n.color),u=(f,p)=>[i+o*f-a*p,s+a*f+o*p],m=Array.from(n.points??[],f=>u(f.x??0,f.y??0)),g=f=>n.colors&&n.colors.length>f?qp(n.colors[f]):d,v=[];switch(n.type){case 0:{let f,p,x,A,b;m.length>=2?([f,p]=m,x=l,A=c||2*l,b=h||Math.hypot(p[0]-f[0],p[1]-f[1])*.3):(f=u(0,0),p=u(l,0),x=c,A=2*c,b=l*.23);let C=Math.hypot(p[0]-f[0],p[1]-f[1]);if(!(C>0))break;let w=(p[0]-f[0])/C,_=(p[1]-f[1])/C,M=-_,U=w;b=Math.min(b,C);let L=[p[0]-w*b,p[1]-_*b],R=x/2,z=A/2;v.push({kind:"polygon",fill:d,pts:[[f[0]+M*R,f[1]+U*R],[L[0]+M*R,L[1]+U*R],[L[0]+M*z,L[1]+U*z],p,[L[0]-M*z,L[1]-U*z],[L[0]-M*R,L[1]-U*R],[f[0]-M*R,f[1]-U*R]]});break}case 1:v.push({kind:"polygon",fill:d,pts:[u(-l/2,-c/2),u(l/2,-c/2),u(l/2,c/2),u(-l/2,c/2)]});break;case 2:case 3:v.push({kind:"ellipse",x:i,y:s,rx:l/2,ry:c/2,yaw:r,fill:d,outline:n.type===3});break;case 4:case 5:{let f=n.type===4?1:2;for(let p=0;p+1<m.length;p+=f)v.push({kind:"polyline",pts:[m[p],m[p+1]],width:l,stroke:g(p)});n.type===4&&!(n.colors&&n.colors.length)&&m.length>1&&(v.length=0,v.push({kind:"polyline",pts:m,width:l,stroke:d}));break}case 6:case 8:m.forEach(([f,p],x)=>v.push({kind:"square",x:f,y:p,w:l,h:n.type===8?c||l:c,fill:g(x)}));break;case 7:m.forEach(([f,p],x)=>v.push({kind:"ellipse",x:f,y:p,rx:l/2,ry:c/2,yaw:0,fill:g(x),outline:!1}));break;case 9:n.text&&v.push({kind:"text",x:i,y:s,height:h,text:n.text,fill:d});break;case 11:for(let f=0;f+2<m.length;f+=3)v.push({kind:"polygon",pts:[m[f],m[f+1],m[f+2]],fill:g(f)});break;default:break}return v}function Zp(n){let e={},t={};for(let{msg:i}of n){let s=Ty[i.type??-1]??`type ${i.type}`;e[s]=(e[s]??0)+1;let r=i.ns??"";t[r]=(t[r]??0)+1}return{byType:e,byNs:t}}var Iy=6e4,Kp=["#2f80ed","#eb5757","#27ae60","#f2994a","#9b51e0","#56ccf2","#bb6bd9","#219653"];function Jp(n){return Kp[n%Kp.length]}var jr=class{canvas=document.createElement("canvas");robots=new Map;scan=null;goal=null;markers=[];markerExpiry=1/0;selected=null;onClick=null;half=11;dirty=!0;raf=0;ro;constructor(e){this.canvas.className="map",e.appendChild(this.canvas),this.ro=new ResizeObserver(()=>this.invalidate()),this.ro.observe(this.canvas),this.canvas.addEventListener("click",i=>{if(!this.onClick)return;let[s,r]=this.toWorld(i.offsetX,i.offsetY);this.onClick(s,r,i)});let t=()=>{this.markerExpiry<=performance.now()&&(this.dirty=!0),this.dirty&&this.draw(),this.raf=requestAnimationFrame(t)};this.raf=requestAnimationFrame(t)}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.canvas.remove()}invalidate(){this.dirty=!0}setPose(e,t,i){let s=this.robots.get(e);s||(s={name:e,pose:null,trail:[],online:!0,colour:i},this.robots.set(e,s));let r=performance.now();s.pose=t;let o=s.trail[s.trail.length-1];for((!o||Math.hypot(o.x-t.x,o.y-t.y)>.05||r-o.t>500)&&s.trail.push({x:t.x,y:t.y,t:r});s.trail.length&&r-s.trail[0].t>Iy;)s.trail.shift();let a=Math.max(Math.abs(t.x),Math.abs(t.y))+1;a>this.half&&(this.half=Math.ceil(a)),this.invalidate()}geometry(){let e=window.devicePixelRatio||1,t=this.canvas.clientWidth,i=this.canvas.clientHeight,s=Math.min(t,i)/(2*this.half);return{dpr:e,w:t,h:i,scale:s,cx:t/2,cy:i/2}}toWorld(e,t){let i=this.geometry();return[(e-i.cx)/i.scale,-(t-i.cy)/i.scale]}toScreen(e,t){let i=this.geometry();return[i.cx+e*i.scale,i.cy-t*i.scale]}draw(){this.dirty=!1;let e=this.geometry();if(e.w===0||e.h===0)return;(this.canvas.width!==Math.round(e.w*e.dpr)||this.canvas.height!==Math.round(e.h*e.dpr))&&(this.canvas.width=Math.round(e.w*e.dpr),this.canvas.height=Math.round(e.h*e.dpr));let t=this.canvas.getContext("2d");t.setTransform(e.dpr,0,0,e.dpr,0,0),t.fillStyle="#0f1720",t.fillRect(0,0,e.w,e.h);let i=(s,r)=>[e.cx+s*e.scale,e.cy-r*e.scale];for(let s=-this.half;s<=this.half;s++){t.strokeStyle=s===0?"#3b4a5a":s%5===0?"#24313e":"#18222c",t.lineWidth=1;let[r,o]=i(s,-this.half),[a,l]=i(s,this.half);t.beginPath(),t.moveTo(r,o),t.lineTo(a,l),t.stroke();let[c,h]=i(-this.half,s),[d,u]=i(this.half,s);t.beginPath(),t.moveTo(c,h),t.lineTo(d,u),t.stroke()}if(t.fillStyle="#5b6b7b",t.font="11px sans-serif",t.fillText(`1 m grid · ${2*this.half} m across`,8,e.h-8),this.markers.length&&this.drawMarkers(t,e.scale,i),this.scan){t.fillStyle="#f2c94c";for(let s=0;s<this.scan.length;s+=2){let[r,o]=i(this.scan[s],this.scan[s+1]);t.fillRect(r-1,o-1,2,2)}}if(this.goal){let[s,r]=i(this.goal.x,this.goal.y);t.strokeStyle="#6fcf97",t.lineWidth=2,t.beginPath(),t.arc(s,r,9,0,Math.PI*2),t.stroke(),t.beginPath(),t.moveTo(s-13,r),t.lineTo(s+13,r),t.moveTo(s,r-13),t.lineTo(s,r+13),t.stroke()}for(let s of this.robots.values()){let r=s.online?s.colour:"#56606a";if(s.trail.length>1&&(t.strokeStyle=r,t.globalAlpha=.55,t.lineWidth=2,t.beginPath(),s.trail.forEach((c,h)=>{let[d,u]=i(c.x,c.y);h===0?t.moveTo(d,u):t.lineTo(d,u)}),t.stroke(),t.globalAlpha=1),!s.pose)continue;let[o,a]=i(s.pose.x,s.pose.y),l=Math.max(9,e.scale*.45);t.save(),t.translate(o,a),t.rotate(-s.pose.yaw),t.fillStyle=r,t.strokeStyle=s.name===this.selected?"#ffffff":"#0b1016",t.lineWidth=2,t.beginPath(),t.moveTo(l,0),t.lineTo(-l*.7,l*.6),t.lineTo(-l*.4,0),t.lineTo(-l*.7,-l*.6),t.closePath(),t.fill(),t.stroke(),t.restore(),t.fillStyle=s.online?"#e0e6ec":"#7b8690",t.font="12px sans-serif",t.fillText(s.online?s.name:`${s.name} (offline)`,o+l+3,a-l*.5)}}drawMarkers(e,t,i){let s=performance.now(),r=this.markers.flatMap(c=>c.live(s));this.markerExpiry=Math.min(...this.markers.map(c=>c.nextExpiry()));let o=0,a=c=>{e.beginPath(),c.forEach(([h,d],u)=>{let[m,g]=i(h,d);u===0?e.moveTo(m,g):e.lineTo(m,g)})},l=c=>{switch(o++,c.kind){case"polygon":a(c.pts),e.closePath(),e.fillStyle=c.fill,e.fill();break;case"ellipse":{let[h,d]=i(c.x,c.y);e.beginPath(),e.ellipse(h,d,Math.max(1,c.rx*t),Math.max(1,c.ry*t),-c.yaw,0,Math.PI*2),e.fillStyle=c.fill,e.fill(),c.outline&&(e.strokeStyle="rgba(11,16,22,0.8)",e.lineWidth=1.5,e.stroke());break}case"polyline":a(c.pts),e.strokeStyle=c.stroke,e.lineWidth=Math.max(1,c.width*t),e.lineJoin="round",e.stroke();break;case"square":{let[h,d]=i(c.x,c.y),u=Math.max(2,c.w*t),m=Math.max(2,c.h*t);e.fillStyle=c.fill,e.fillRect(h-u/2,d-m/2,u,m);break}case"text":{let[h,d]=i(c.x,c.y);e.font=`${Math.max(9,c.height*t)}px sans-serif`,e.textAlign="center",e.textBaseline="middle",e.fillStyle=c.fill,e.fillText(c.text,h,d),e.textAlign="start",e.textBaseline="alphabetic";break}}};for(let c of r)Yp(c.msg).forEach(l);vt.markers={...Zp(r),drawn:r.length,shapes:o}}};function Au(n,e){let t=e.filter(r=>r.name.startsWith(`/${n}/`)),i=r=>t.find(o=>o.type===r),s=i("geometry_msgs/msg/PoseStamped")??i("nav_msgs/msg/Odometry")??i("geometry_msgs/msg/PoseWithCovarianceStamped");return s?{topic:s.name,type:s.type}:null}function Py(n,e){let t=0,i=0,s={};for(let r of e)if(r.name.startsWith(`/${n}/`)){t+=r.rate_hz,i+=r.bandwidth_bps;for(let[o,a]of Object.entries(r.drops??{}))a&&(s[o]=(s[o]??0)+a)}return{rate:t,bw:i,drops:s}}function jp(n,e,t){n.innerHTML="";let i=te("div","fleet"),s=te("div","panel mapbox");s.appendChild(te("h2","","Fleet map"));let r=te("div","panel side");r.appendChild(te("h2","","Robots"));let o=te("div","robotlist");r.appendChild(o),i.append(s,r),n.appendChild(i);let a=new jr(s);a.onClick=(g,v)=>{let f=null,p=1.2;for(let x of a.robots.values()){if(!x.pose)continue;let A=Math.hypot(x.pose.x-g,x.pose.y-v);A<p&&(f=x.name,p=A)}f&&t(f)};let l=new Map,c=new Map,h=!1;async function d(){let g=[],v=[];try{[{robots:g},{topics:v}]=await Promise.all([gn("/api/v1/robots"),gn("/api/v1/topics")])}catch(f){o.textContent=`cannot list robots: ${f.message}`;return}if(!h){g.sort((f,p)=>f.name.localeCompare(p.name,void 0,{numeric:!0})),g.forEach(f=>{c.has(f.name)||c.set(f.name,Jp(c.size))});for(let f of g){let p=Au(f.name,v),x=p?.topic;if(f.online&&p&&!l.has(x)){let b=c.get(f.name);l.set(x,e.subscribe(p.topic,C=>{let w=Il(C);w&&(a.setPose(f.name,w,b),vt.poses[f.name]={...w,at:Date.now()},On("fleet-pose"))},{type:p.type,throttle_rate:100,queue_length:1,compression:"none"}))}let A=a.robots.get(f.name);A&&A.online!==f.online&&(A.online=f.online,a.invalidate())}u(g,v)}}function u(g,v){o.innerHTML="",g.length===0&&o.appendChild(te("p","muted","No robots visible to you yet."));for(let f of g){let p=Py(f.name,v),x=te("div",`robot ${f.online?"online":"offline"}`);x.dataset.robot=f.name;let A=te("div","robot-head"),b=te("span","dot");b.style.background=f.online?c.get(f.name):"#56606a",A.append(b,te("b","",f.name),te("span",f.online?"badge ok":"badge off",f.online?"online":`offline · gone ${_r(f.last_seen_ms)}`)),x.appendChild(A);let C=te("dl","kv"),w=(_,M,U="")=>{let L=te("dt","",_),R=te("dd","",M);U&&(R.title=U),C.append(L,R)};if(f.hub?w("hub",f.hub,"connected to this other hub of the federation"):w("last seen",_r(f.last_seen_ms)),f.online&&!f.hub){w("RTT",f.rtt_ms!=null?`${Nt(f.rtt_ms)} ms`:"–"),w("goodput",zn(f.link_rate_bps),"what the robot's link delivered (its link report)"),w("msg/s",Nt(p.rate),`${zn(p.bw)} over ${f.topics.length} topics`);let _=Object.entries(p.drops);w("drops",_.length?_.map(([M,U])=>`${M} ${U}`).join(", "):"none"),w("clock offset",f.clock_offset_ms!=null?`${Nt(f.clock_offset_ms)} ms`:"–"),w("share",f.share_bps?zn(f.share_bps):"unlimited","capacity share of the robot's site")}x.appendChild(C),x.addEventListener("click",()=>t(f.name)),o.appendChild(x)}}d();let m=window.setInterval(d,1e3);return()=>{h=!0,clearInterval(m);for(let g of l.values())g();a.destroy()}}var Ly="uplot",Ny="u-hz",Dy="u-vt",Uy="u-title",Oy="u-wrap",Fy="u-under",By="u-over",ky="u-axis",vr="u-off",zy="u-select",Gy="u-cursor-x",Hy="u-cursor-y",Vy="u-cursor-pt",Wy="u-legend",Xy="u-live",$y="u-inline",qy="u-series",Yy="u-marker",Qp="u-label",Zy="u-value",ca="width",ha="height";var em="bottom",Qr="left",Ru="right",Xu="#000",tm=Xu+"0",Cu="mousemove",nm="mousedown",Iu="mouseup",im="mouseenter",sm="mouseleave",rm="dblclick",Ky="resize",Jy="scroll",om="change",Ol="dppxchange",$u="--",oo=typeof window<"u",Uu=oo?document:null,to=oo?window:null,jy=oo?navigator:null,Dt,Ll;function Ou(){let n=devicePixelRatio;Dt!=n&&(Dt=n,Ll&&Bu(om,Ll,Ou),Ll=matchMedia(`(min-resolution: ${Dt-.001}dppx) and (max-resolution: ${Dt+.001}dppx)`),br(om,Ll,Ou),to.dispatchEvent(new CustomEvent(Ol)))}function li(n,e){if(e!=null){let t=n.classList;!t.contains(e)&&t.add(e)}}function Fu(n,e){let t=n.classList;t.contains(e)&&t.remove(e)}function Jt(n,e,t){n.style[e]=t+"px"}function Pi(n,e,t,i){let s=Uu.createElement(n);return e!=null&&li(s,e),t?.insertBefore(s,i),s}function Mi(n,e){return Pi("div",n,e)}var am=new WeakMap;function ji(n,e,t,i,s){let r="translate("+e+"px,"+t+"px)",o=am.get(n);r!=o&&(n.style.transform=r,am.set(n,r),e<0||t<0||e>i||t>s?li(n,vr):Fu(n,vr))}var lm=new WeakMap;function cm(n,e,t){let i=e+t,s=lm.get(n);i!=s&&(lm.set(n,i),n.style.background=e,n.style.borderColor=t)}var hm=new WeakMap;function um(n,e,t,i){let s=e+""+t,r=hm.get(n);s!=r&&(hm.set(n,s),n.style.height=t+"px",n.style.width=e+"px",n.style.marginLeft=i?-e/2+"px":0,n.style.marginTop=i?-t/2+"px":0)}var qu={passive:!0},Qy={...qu,capture:!0};function br(n,e,t,i){e.addEventListener(n,t,i?Qy:qu)}function Bu(n,e,t,i){e.removeEventListener(n,t,qu)}oo&&Ou();function Li(n,e,t,i){let s;t=t||0,i=i||e.length-1;let r=i<=2147483647;for(;i-t>1;)s=r?t+i>>1:ci((t+i)/2),e[s]<n?t=s:i=s;return n-e[t]<=e[i]-n?t:i}function km(n){return(t,i,s)=>{let r=-1,o=-1;for(let a=i;a<=s;a++)if(n(t[a])){r=a;break}for(let a=s;a>=i;a--)if(n(t[a])){o=a;break}return[r,o]}}var zm=n=>n!=null,Gm=n=>n!=null&&n>0,kl=km(zm),ex=km(Gm);function tx(n,e,t,i=0,s=!1){let r=s?ex:kl,o=s?Gm:zm;[e,t]=r(n,e,t);let a=n[e],l=n[e];if(e>-1)if(i==1)a=n[e],l=n[t];else if(i==-1)a=n[t],l=n[e];else for(let c=e;c<=t;c++){let h=n[c];o(h)&&(h<a?a=h:h>l&&(l=h))}return[a??Wt,l??-Wt]}function zl(n,e,t,i){let s=pm(n),r=pm(e);n==e&&(s==-1?(n*=t,e/=t):(n/=t,e*=t));let o=t==10?ms:Hm,a=s==1?ci:wi,l=r==1?wi:ci,c=a(o(Sn(n))),h=l(o(Sn(e))),d=no(t,c),u=no(t,h);return t==10&&(c<0&&(d=Xt(d,-c)),h<0&&(u=Xt(u,-h))),i||t==2?(n=d*s,e=u*r):(n=$m(n,d),e=Gl(e,u)),[n,e]}function Yu(n,e,t,i){let s=zl(n,e,t,i);return n==0&&(s[0]=0),e==0&&(s[1]=0),s}var Zu=.1,dm={mode:3,pad:Zu},da={pad:0,soft:null,mode:0},nx={min:da,max:da};function Fl(n,e,t,i){return Hl(t)?fm(n,e,t):(da.pad=t,da.soft=i?0:null,da.mode=i?3:0,fm(n,e,nx))}function It(n,e){return n??e}function ix(n,e,t){for(e=It(e,0),t=It(t,n.length-1);e<=t;){if(n[e]!=null)return!0;e++}return!1}function fm(n,e,t){let i=t.min,s=t.max,r=It(i.pad,0),o=It(s.pad,0),a=It(i.hard,-Wt),l=It(s.hard,Wt),c=It(i.soft,Wt),h=It(s.soft,-Wt),d=It(i.mode,0),u=It(s.mode,0),m=e-n,g=ms(m),v=Zn(Sn(n),Sn(e)),f=ms(v),p=Sn(f-g);(m<1e-24||p>10)&&(m=0,(n==0||e==0)&&(m=1e-24,d==2&&c!=Wt&&(r=0),u==2&&h!=-Wt&&(o=0)));let x=m||v||1e3,A=ms(x),b=no(10,ci(A)),C=x*(m==0?n==0?.1:1:r),w=Xt($m(n-C,b/10),24),_=n>=c&&(d==1||d==3&&w<=c||d==2&&w>=c)?c:Wt,M=Zn(a,w<_&&n>=_?_:Ni(_,w)),U=x*(m==0?e==0?.1:1:o),L=Xt(Gl(e+U,b/10),24),R=e<=h&&(u==1||u==3&&L>=h||u==2&&L<=h)?h:-Wt,z=Ni(l,L>R&&e<=R?R:Zn(R,L));return M==z&&M==0&&(z=100),[M,z]}var sx=new Intl.NumberFormat(oo?jy.language:"en-US"),Ku=n=>sx.format(n),hi=Math,Ul=hi.PI,Sn=hi.abs,ci=hi.floor,bn=hi.round,wi=hi.ceil,Ni=hi.min,Zn=hi.max,no=hi.pow,pm=hi.sign,ms=hi.log10,Hm=hi.log2,rx=(n,e=1)=>hi.sinh(n)*e,Pu=(n,e=1)=>hi.asinh(n/e),Wt=1/0;function mm(n){return(ms((n^n>>31)-(n>>31))|0)+1}function ku(n,e,t){return Ni(Zn(n,e),t)}function Vm(n){return typeof n=="function"}function Et(n){return Vm(n)?n:()=>n}var ox=()=>{},Wm=n=>n,Xm=(n,e)=>e,ax=n=>null,gm=n=>!0,_m=(n,e)=>n==e,lx=/\.\d*?(?=9{6,}|0{6,})/gm,Sr=n=>{if(Ym(n)||Xs.has(n))return n;let e=`${n}`,t=e.match(lx);if(t==null)return n;let i=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${Sr(s)}e${r}`}return Xt(n,i)};function yr(n,e){return Sr(Xt(Sr(n/e))*e)}function Gl(n,e){return Sr(wi(Sr(n/e))*e)}function $m(n,e){return Sr(ci(Sr(n/e))*e)}function Xt(n,e=0){if(Ym(n))return n;let t=10**e,i=n*t*(1+Number.EPSILON);return bn(i)/t}var Xs=new Map;function qm(n){return((""+n).split(".")[1]||"").length}function pa(n,e,t,i){let s=[],r=i.map(qm);for(let o=e;o<t;o++){let a=Sn(o),l=Xt(no(n,o),a);for(let c=0;c<i.length;c++){let h=n==10?+`${i[c]}e${o}`:i[c]*l,d=(o>=0?0:a)+(o>=r[c]?0:r[c]),u=n==10?h:Xt(h,d);s.push(u),Xs.set(u,d)}}return s}var fa={},Ju=[],io=[null,null],Ws=Array.isArray,Ym=Number.isInteger,cx=n=>n===void 0;function ym(n){return typeof n=="string"}function Hl(n){let e=!1;if(n!=null){let t=n.constructor;e=t==null||t==Object}return e}function hx(n){return n!=null&&typeof n=="object"}var ux=Object.getPrototypeOf(Uint8Array),Zm="__proto__";function so(n,e=Hl){let t;if(Ws(n)){let i=n.find(s=>s!=null);if(Ws(i)||e(i)){t=Array(n.length);for(let s=0;s<n.length;s++)t[s]=so(n[s],e)}else t=n.slice()}else if(n instanceof ux)t=n.slice();else if(e(n)){t={};for(let i in n)i!=Zm&&(t[i]=so(n[i],e))}else t=n;return t}function yn(n){let e=arguments;for(let t=1;t<e.length;t++){let i=e[t];for(let s in i)s!=Zm&&(Hl(n[s])?yn(n[s],so(i[s])):n[s]=so(i[s]))}return n}var dx=0,fx=1,px=2;function mx(n,e,t){for(let i=0,s,r=-1;i<e.length;i++){let o=e[i];if(o>r){for(s=o-1;s>=0&&n[s]==null;)n[s--]=null;for(s=o+1;s<t&&n[s]==null;)n[r=s++]=null}}}function gx(n,e){if(xx(n)){let o=n[0].slice();for(let a=1;a<n.length;a++)o.push(...n[a].slice(1));return vx(o[0])||(o=yx(o)),o}let t=new Set;for(let o=0;o<n.length;o++){let l=n[o][0],c=l.length;for(let h=0;h<c;h++)t.add(l[h])}let i=[Array.from(t).sort((o,a)=>o-a)],s=i[0].length,r=new Map;for(let o=0;o<s;o++)r.set(i[0][o],o);for(let o=0;o<n.length;o++){let a=n[o],l=a[0];for(let c=1;c<a.length;c++){let h=a[c],d=Array(s).fill(void 0),u=e?e[o][c]:fx,m=[];for(let g=0;g<h.length;g++){let v=h[g],f=r.get(l[g]);v===null?u!=dx&&(d[f]=v,u==px&&m.push(f)):d[f]=v}mx(d,m,s),i.push(d)}}return i}var _x=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function yx(n){let e=n[0],t=e.length,i=Array(t);for(let r=0;r<i.length;r++)i[r]=r;i.sort((r,o)=>e[r]-e[o]);let s=[];for(let r=0;r<n.length;r++){let o=n[r],a=Array(t);for(let l=0;l<t;l++)a[l]=o[i[l]];s.push(a)}return s}function xx(n){let e=n[0][0],t=e.length;for(let i=1;i<n.length;i++){let s=n[i][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function vx(n,e=100){let t=n.length;if(t<=1)return!0;let i=0,s=t-1;for(;i<=s&&n[i]==null;)i++;for(;s>=i&&n[s]==null;)s--;if(s<=i)return!0;let r=Zn(1,ci((s-i+1)/e));for(let o=n[i],a=i+r;a<=s;a+=r){let l=n[a];if(l!=null){if(l<=o)return!1;o=l}}return!0}var Km=["January","February","March","April","May","June","July","August","September","October","November","December"],Jm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function jm(n){return n.slice(0,3)}var bx=Jm.map(jm),Sx=Km.map(jm),Mx={MMMM:Km,MMM:Sx,WWWW:Jm,WWW:bx};function la(n){return(n<10?"0":"")+n}function wx(n){return(n<10?"00":n<100?"0":"")+n}var Ex={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,e)=>e.MMMM[n.getMonth()],MMM:(n,e)=>e.MMM[n.getMonth()],MM:n=>la(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>la(n.getDate()),D:n=>n.getDate(),WWWW:(n,e)=>e.WWWW[n.getDay()],WWW:(n,e)=>e.WWW[n.getDay()],HH:n=>la(n.getHours()),H:n=>n.getHours(),h:n=>{let e=n.getHours();return e==0?12:e>12?e-12:e},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>la(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>la(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>wx(n.getMilliseconds())};function ju(n,e){e=e||Mx;let t=[],i=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=i.exec(n);)t.push(s[0][0]=="{"?Ex[s[1]]:s[0]);return r=>{let o="";for(let a=0;a<t.length;a++)o+=typeof t[a]=="string"?t[a]:t[a](r,e);return o}}var Tx=new Intl.DateTimeFormat().resolvedOptions().timeZone;function Ax(n,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+n+n.getTimezoneOffset()*6e4):e==Tx?t=n:(t=new Date(n.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(n.getMilliseconds())),t}var Qm=n=>n%1==0,Bl=[1,2,2.5,5],Rx=pa(10,-32,0,Bl),eg=pa(10,0,32,Bl),Cx=eg.filter(Qm),xr=Rx.concat(eg),Qu=`
`,tg="{YYYY}",xm=Qu+tg,ng="{M}/{D}",ua=Qu+ng,Nl=ua+"/{YY}",ig="{aa}",Ix="{h}:{mm}",eo=Ix+ig,vm=Qu+eo,bm=":{ss}",Ot=null;function sg(n){let e=n*1e3,t=e*60,i=t*60,s=i*24,r=s*30,o=s*365,l=(n==1?pa(10,0,3,Bl).filter(Qm):pa(10,-3,0,Bl)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,i,i*2,i*3,i*4,i*6,i*8,i*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,o,o*2,o*5,o*10,o*25,o*50,o*100]),c=[[o,tg,Ot,Ot,Ot,Ot,Ot,Ot,1],[s*28,"{MMM}",xm,Ot,Ot,Ot,Ot,Ot,1],[s,ng,xm,Ot,Ot,Ot,Ot,Ot,1],[i,"{h}"+ig,Nl,Ot,ua,Ot,Ot,Ot,1],[t,eo,Nl,Ot,ua,Ot,Ot,Ot,1],[e,bm,Nl+" "+eo,Ot,ua+" "+eo,Ot,vm,Ot,1],[n,bm+".{fff}",Nl+" "+eo,Ot,ua+" "+eo,Ot,vm,Ot,1]];function h(d){return(u,m,g,v,f,p)=>{let x=[],A=f>=o,b=f>=r&&f<o,C=d(g),w=Xt(C*n,3),_=Lu(C.getFullYear(),A?0:C.getMonth(),b||A?1:C.getDate()),M=Xt(_*n,3);if(b||A){let U=b?f/r:0,L=A?f/o:0,R=w==M?w:Xt(Lu(_.getFullYear()+L,_.getMonth()+U,1)*n,3),z=new Date(bn(R/n)),F=z.getFullYear(),P=z.getMonth();for(let B=0;R<=v;B++){let X=Lu(F+L*B,P+U*B,1),D=X-d(Xt(X*n,3));R=Xt((+X+D)*n,3),R<=v&&x.push(R)}}else{let U=f>=s?s:f,L=ci(g)-ci(w),R=M+L+Gl(w-M,U);x.push(R);let z=d(R),F=z.getHours()+z.getMinutes()/t+z.getSeconds()/i,P=f/i,B=u.axes[m]._space,X=p/B;for(;R=Xt(R+f,n==1?0:3),!(R>v);)if(P>1){let D=ci(Xt(F+P,6))%24,W=d(R).getHours()-D;W>1&&(W=-1),R-=W*i,F=(F+P)%24;let $=x[x.length-1];Xt((R-$)/f,3)*X>=.7&&x.push(R)}else x.push(R)}return x}}return[l,c,h]}var[Px,Lx,Nx]=sg(1),[Dx,Ux,Ox]=sg(.001);pa(2,-53,53,[1]);function Sm(n,e){return n.map(t=>t.map((i,s)=>s==0||s==8||i==null?i:e(s==1||t[8]==0?i:t[1]+i)))}function Mm(n,e){return(t,i,s,r,o)=>{let a=e.find(g=>o>=g[0])||e[e.length-1],l,c,h,d,u,m;return i.map(g=>{let v=n(g),f=v.getFullYear(),p=v.getMonth(),x=v.getDate(),A=v.getHours(),b=v.getMinutes(),C=v.getSeconds(),w=f!=l&&a[2]||p!=c&&a[3]||x!=h&&a[4]||A!=d&&a[5]||b!=u&&a[6]||C!=m&&a[7]||a[1];return l=f,c=p,h=x,d=A,u=b,m=C,w(v)})}}function Fx(n,e){let t=ju(e);return(i,s,r,o,a)=>s.map(l=>t(n(l)))}function Lu(n,e,t){return new Date(n,e,t)}function wm(n,e){return e(n)}var Bx="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function Em(n,e){return(t,i,s,r)=>r==null?$u:e(n(i))}function kx(n,e){let t=n.series[e];return t.width?t.stroke(n,e):t.points.width?t.points.stroke(n,e):null}function zx(n,e){return n.series[e].fill(n,e)}var Gx={show:!0,live:!0,isolate:!1,mount:ox,markers:{show:!0,width:2,stroke:kx,fill:zx,dash:"solid"},idx:null,idxs:null,values:[]};function Hx(n,e){let t=n.cursor.points,i=Mi(),s=t.size(n,e);Jt(i,ca,s),Jt(i,ha,s);let r=s/-2;Jt(i,"marginLeft",r),Jt(i,"marginTop",r);let o=t.width(n,e,s);return o&&Jt(i,"borderWidth",o),i}function Vx(n,e){let t=n.series[e].points;return t._fill||t._stroke}function Wx(n,e){let t=n.series[e].points;return t._stroke||t._fill}function Xx(n,e){return n.series[e].points.size}var Nu=[0,0];function $x(n,e,t){return Nu[0]=e,Nu[1]=t,Nu}function Dl(n,e,t,i=!0){return s=>{s.button==0&&(!i||s.target==e)&&t(s)}}function Du(n,e,t,i=!0){return s=>{(!i||s.target==e)&&t(s)}}var qx={show:!0,x:!0,y:!0,lock:!1,move:$x,points:{one:!1,show:Hx,size:Xx,width:0,stroke:Wx,fill:Vx},bind:{mousedown:Dl,mouseup:Dl,click:Dl,dblclick:Dl,mousemove:Du,mouseleave:Du,mouseenter:Du},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,e,t,i,s)=>i-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},rg={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},ed=yn({},rg,{filter:Xm}),og=yn({},ed,{size:10}),ag=yn({},rg,{show:!1}),td='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',lg="bold "+td,cg=1.5,Tm={show:!0,scale:"x",stroke:Xu,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:lg,side:2,grid:ed,ticks:og,border:ag,font:td,lineGap:cg,rotate:0},Yx="Value",Zx="Time",Am={show:!0,scale:"x",auto:!1,sorted:1,min:Wt,max:-Wt,idxs:[]};function Kx(n,e,t,i,s){return e.map(r=>r==null?"":Ku(r))}function Jx(n,e,t,i,s,r,o){let a=[],l=Xs.get(s)||0;t=o?t:Xt(Gl(t,s),l);for(let c=t;c<=i;c=Xt(c+s,l))a.push(Object.is(c,-0)?0:c);return a}function zu(n,e,t,i,s,r,o){let a=[],l=n.scales[n.axes[e].scale].log,c=l==10?ms:Hm,h=ci(c(t));s=no(l,h),l==10&&(s=xr[Li(s,xr)]);let d=t,u=s*l;l==10&&(u=xr[Li(u,xr)]);do a.push(d),d=d+s,l==10&&!Xs.has(d)&&(d=Xt(d,Xs.get(s))),d>=u&&(s=d,u=s*l,l==10&&(u=xr[Li(u,xr)]));while(d<=i);return a}function jx(n,e,t,i,s,r,o){let l=n.scales[n.axes[e].scale].asinh,c=i>l?zu(n,e,Zn(l,t),i,s):[l],h=i>=0&&t<=0?[0]:[];return(t<-l?zu(n,e,Zn(l,-i),-t,s):[l]).reverse().map(u=>-u).concat(h,c)}var hg=/./,Qx=/[12357]/,ev=/[125]/,Rm=/1/,Gu=(n,e,t,i)=>n.map((s,r)=>e==4&&s==0||r%i==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function tv(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=n.scales[o],l=n.valToPos,c=r._space,h=l(10,o),d=l(9,o)-h>=c?hg:l(7,o)-h>=c?Qx:l(5,o)-h>=c?ev:Rm;if(d==Rm){let u=Sn(l(1,o)-h);if(u<c)return Gu(e.slice().reverse(),a.distr,d,wi(c/u)).reverse()}return Gu(e,a.distr,d,1)}function nv(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=r._space,l=n.valToPos,c=Sn(l(1,o)-l(2,o));return c<a?Gu(e.slice().reverse(),3,hg,wi(a/c)).reverse():e}function iv(n,e,t,i){return i==null?$u:e==null?"":Ku(e)}var Cm={show:!0,scale:"y",stroke:Xu,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:lg,side:3,grid:ed,ticks:og,border:ag,font:td,lineGap:cg,rotate:0};function sv(n,e){let t=3+(n||1)*2;return Xt(t*e,3)}function rv(n,e){let{scale:t,idxs:i}=n.series[0],s=n._data[0],r=n.valToPos(s[i[0]],t,!0),o=n.valToPos(s[i[1]],t,!0),a=Sn(o-r),l=n.series[e],c=a/(l.points.space*Dt);return i[1]-i[0]<=c}var Im={scale:null,auto:!0,sorted:0,min:Wt,max:-Wt},ug=(n,e,t,i,s)=>s,Pm={show:!0,auto:!0,sorted:0,gaps:ug,alpha:1,facets:[yn({},Im,{scale:"x"}),yn({},Im,{scale:"y"})]},Lm={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:ug,alpha:1,points:{show:rv,filter:null},values:null,min:Wt,max:-Wt,idxs:[],path:null,clip:null};function ov(n,e,t,i,s){return t/10}var dg={time:!0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},av=yn({},dg,{time:!1,ori:1}),Nm={};function fg(n,e){let t=Nm[n];return t||(t={key:n,plots:[],sub(i){t.plots.push(i)},unsub(i){t.plots=t.plots.filter(s=>s!=i)},pub(i,s,r,o,a,l,c){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(i,s,r,o,a,l,c)}},n!=null&&(Nm[n]=t)),t}var ro=1,Hu=2;function Mr(n,e,t){let i=n.mode,s=n.series[e],r=i==2?n._data[e]:n._data,o=n.scales,a=n.bbox,l=r[0],c=i==2?r[1]:r[e],h=i==2?o[s.facets[0].scale]:o[n.series[0].scale],d=i==2?o[s.facets[1].scale]:o[s.scale],u=a.left,m=a.top,g=a.width,v=a.height,f=n.valToPosH,p=n.valToPosV;return h.ori==0?t(s,l,c,h,d,f,p,u,m,g,v,Wl,ao,$l,mg,_g):t(s,l,c,h,d,p,f,m,u,v,g,Xl,lo,sd,gg,yg)}function nd(n,e){let t=0,i=0,s=It(n.bands,Ju);for(let r=0;r<s.length;r++){let o=s[r];o.series[0]==e?t=o.dir:o.series[1]==e&&(o.dir==1?i|=1:i|=2)}return[t,i==1?-1:i==2?1:i==3?2:0]}function lv(n,e,t,i,s){let r=n.mode,o=n.series[e],a=r==2?o.facets[1].scale:o.scale,l=n.scales[a];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function gs(n,e,t,i,s,r){return Mr(n,e,(o,a,l,c,h,d,u,m,g,v,f)=>{let p=o.pxRound,x=c.dir*(c.ori==0?1:-1),A=c.ori==0?ao:lo,b,C;x==1?(b=t,C=i):(b=i,C=t);let w=p(d(a[b],c,v,m)),_=p(u(l[b],h,f,g)),M=p(d(a[C],c,v,m)),U=p(u(r==1?h.max:h.min,h,f,g)),L=new Path2D(s);return A(L,M,U),A(L,w,U),A(L,w,_),L})}function Vl(n,e,t,i,s,r){let o=null;if(n.length>0){o=new Path2D;let a=e==0?$l:sd,l=t;for(let d=0;d<n.length;d++){let u=n[d];if(u[1]>u[0]){let m=u[0]-l;m>0&&a(o,l,i,m,i+r),l=u[1]}}let c=t+s-l,h=10;c>0&&a(o,l,i-h/2,c,i+r+h)}return o}function cv(n,e,t){let i=n[n.length-1];i&&i[0]==e?i[1]=t:n.push([e,t])}function id(n,e,t,i,s,r,o){let a=[],l=n.length;for(let c=s==1?t:i;c>=t&&c<=i;c+=s)if(e[c]===null){let d=c,u=c;if(s==1)for(;++c<=i&&e[c]===null;)u=c;else for(;--c>=t&&e[c]===null;)u=c;let m=r(n[d]),g=u==d?m:r(n[u]),v=d-s;m=o<=0&&v>=0&&v<l?r(n[v]):m;let p=u+s;g=o>=0&&p>=0&&p<l?r(n[p]):g,g>=m&&a.push([m,g])}return a}function Dm(n){return n==0?Wm:n==1?bn:e=>yr(e,n)}function pg(n){let e=n==0?Wl:Xl,t=n==0?(s,r,o,a,l,c)=>{s.arcTo(r,o,a,l,c)}:(s,r,o,a,l,c)=>{s.arcTo(o,r,l,a,c)},i=n==0?(s,r,o,a,l)=>{s.rect(r,o,a,l)}:(s,r,o,a,l)=>{s.rect(o,r,l,a)};return(s,r,o,a,l,c=0,h=0)=>{c==0&&h==0?i(s,r,o,a,l):(c=Ni(c,a/2,l/2),h=Ni(h,a/2,l/2),e(s,r+c,o),t(s,r+a,o,r+a,o+l,c),t(s,r+a,o+l,r,o+l,h),t(s,r,o+l,r,o,h),t(s,r,o,r+a,o,c),s.closePath())}}var Wl=(n,e,t)=>{n.moveTo(e,t)},Xl=(n,e,t)=>{n.moveTo(t,e)},ao=(n,e,t)=>{n.lineTo(e,t)},lo=(n,e,t)=>{n.lineTo(t,e)},$l=pg(0),sd=pg(1),mg=(n,e,t,i,s,r)=>{n.arc(e,t,i,s,r)},gg=(n,e,t,i,s,r)=>{n.arc(t,e,i,s,r)},_g=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(e,t,i,s,r,o)},yg=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(t,e,s,i,o,r)};function xg(n){return(e,t,i,s,r)=>Mr(e,t,(o,a,l,c,h,d,u,m,g,v,f)=>{let{pxRound:p,points:x}=o,A,b;c.ori==0?(A=Wl,b=mg):(A=Xl,b=gg);let C=Xt(x.width*Dt,3),w=(x.size-x.width)/2*Dt,_=Xt(w*2,3),M=new Path2D,U=new Path2D,{left:L,top:R,width:z,height:F}=e.bbox;$l(U,L-_,R-_,z+_*2,F+_*2);let P=B=>{if(l[B]!=null){let X=p(d(a[B],c,v,m)),D=p(u(l[B],h,f,g));A(M,X+w,D),b(M,X,D,w,0,Ul*2)}};if(r)r.forEach(P);else for(let B=i;B<=s;B++)P(B);return{stroke:C>0?M:null,fill:M,clip:U,flags:ro|Hu}})}function vg(n){return(e,t,i,s,r,o)=>{i!=s&&(r!=i&&o!=i&&n(e,t,i),r!=s&&o!=s&&n(e,t,s),n(e,t,o))}}var hv=vg(ao),uv=vg(lo);function bg(n){let e=It(n?.alignGaps,0);return(t,i,s,r)=>Mr(t,i,(o,a,l,c,h,d,u,m,g,v,f)=>{[s,r]=kl(l,s,r);let p=o.pxRound,x=F=>p(d(F,c,v,m)),A=F=>p(u(F,h,f,g)),b,C;c.ori==0?(b=ao,C=hv):(b=lo,C=uv);let w=c.dir*(c.ori==0?1:-1),_={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:ro},M=_.stroke,U=!1;if(r-s>=v*4){let F=le=>t.posToVal(le,c.key,!0),P=null,B=null,X,D,ne,q=x(a[w==1?s:r]),W=x(a[s]),$=x(a[r]),re=F(w==1?W+1:$-1);for(let le=w==1?s:r;le>=s&&le<=r;le+=w){let Q=a[le],fe=(w==1?Q<re:Q>re)?q:x(Q),ve=l[le];fe==q?ve!=null?(D=ve,P==null?(b(M,fe,A(D)),X=P=B=D):D<P?P=D:D>B&&(B=D)):ve===null&&(U=!0):(P!=null&&C(M,q,A(P),A(B),A(X),A(D)),ve!=null?(D=ve,b(M,fe,A(D)),P=B=X=D):(P=B=null,ve===null&&(U=!0)),q=fe,re=F(q+w))}P!=null&&P!=B&&ne!=q&&C(M,q,A(P),A(B),A(X),A(D))}else for(let F=w==1?s:r;F>=s&&F<=r;F+=w){let P=l[F];P===null?U=!0:P!=null&&b(M,x(a[F]),A(P))}let[R,z]=nd(t,i);if(o.fill!=null||R!=0){let F=_.fill=new Path2D(M),P=o.fillTo(t,i,o.min,o.max,R),B=A(P),X=x(a[s]),D=x(a[r]);w==-1&&([D,X]=[X,D]),b(F,D,B),b(F,X,B)}if(!o.spanGaps){let F=[];U&&F.push(...id(a,l,s,r,w,x,e)),_.gaps=F=o.gaps(t,i,s,r,F),_.clip=Vl(F,c.ori,m,g,v,f)}return z!=0&&(_.band=z==2?[gs(t,i,s,r,M,-1),gs(t,i,s,r,M,1)]:gs(t,i,s,r,M,z)),_})}function dv(n){let e=It(n.align,1),t=It(n.ascDesc,!1),i=It(n.alignGaps,0),s=It(n.extend,!1);return(r,o,a,l)=>Mr(r,o,(c,h,d,u,m,g,v,f,p,x,A)=>{[a,l]=kl(d,a,l);let b=c.pxRound,{left:C,width:w}=r.bbox,_=W=>b(g(W,u,x,f)),M=W=>b(v(W,m,A,p)),U=u.ori==0?ao:lo,L={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:ro},R=L.stroke,z=u.dir*(u.ori==0?1:-1),F=M(d[z==1?a:l]),P=_(h[z==1?a:l]),B=P,X=P;s&&e==-1&&(X=C,U(R,X,F)),U(R,P,F);for(let W=z==1?a:l;W>=a&&W<=l;W+=z){let $=d[W];if($==null)continue;let re=_(h[W]),le=M($);e==1?U(R,re,F):U(R,B,le),U(R,re,le),F=le,B=re}let D=B;s&&e==1&&(D=C+w,U(R,D,F));let[ne,q]=nd(r,o);if(c.fill!=null||ne!=0){let W=L.fill=new Path2D(R),$=c.fillTo(r,o,c.min,c.max,ne),re=M($);U(W,D,re),U(W,X,re)}if(!c.spanGaps){let W=[];W.push(...id(h,d,a,l,z,_,i));let $=c.width*Dt/2,re=t||e==1?$:-$,le=t||e==-1?-$:$;W.forEach(Q=>{Q[0]+=re,Q[1]+=le}),L.gaps=W=c.gaps(r,o,a,l,W),L.clip=Vl(W,u.ori,f,p,x,A)}return q!=0&&(L.band=q==2?[gs(r,o,a,l,R,-1),gs(r,o,a,l,R,1)]:gs(r,o,a,l,R,q)),L})}function Um(n,e,t,i,s,r,o=Wt){if(n.length>1){let a=null;for(let l=0,c=1/0;l<n.length;l++)if(e[l]!==void 0){if(a!=null){let h=Sn(n[l]-n[a]);h<c&&(c=h,o=Sn(t(n[l],i,s,r)-t(n[a],i,s,r)))}a=l}}return o}function fv(n){n=n||fa;let e=It(n.size,[.6,Wt,1]),t=n.align||0,i=n.gap||0,s=n.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;let r=Et(s),o=1-e[0],a=It(e[1],Wt),l=It(e[2],1),c=It(n.disp,fa),h=It(n.each,m=>{}),{fill:d,stroke:u}=c;return(m,g,v,f)=>Mr(m,g,(p,x,A,b,C,w,_,M,U,L,R)=>{let z=p.pxRound,F=t,P=i*Dt,B=a*Dt,X=l*Dt,D,ne;b.ori==0?[D,ne]=r(m,g):[ne,D]=r(m,g);let q=b.dir*(b.ori==0?1:-1),W=b.ori==0?$l:sd,$=b.ori==0?h:(be,je,ht,Ae,Vt,We,Ze)=>{h(be,je,ht,Vt,Ae,Ze,We)},re=It(m.bands,Ju).find(be=>be.series[0]==g),le=re!=null?re.dir:0,Q=p.fillTo(m,g,p.min,p.max,le),me=z(_(Q,C,R,U)),fe,ve,ye,Ve=L,Je=z(p.width*Dt),Ne=!1,qe=null,Qe=null,pe=null,Xe=null;d!=null&&(Je==0||u!=null)&&(Ne=!0,qe=d.values(m,g,v,f),Qe=new Map,new Set(qe).forEach(be=>{be!=null&&Qe.set(be,new Path2D)}),Je>0&&(pe=u.values(m,g,v,f),Xe=new Map,new Set(pe).forEach(be=>{be!=null&&Xe.set(be,new Path2D)})));let{x0:et,size:Gt}=c;if(et!=null&&Gt!=null){F=1,x=et.values(m,g,v,f),et.unit==2&&(x=x.map(ht=>m.posToVal(M+ht*L,b.key,!0)));let be=Gt.values(m,g,v,f);Gt.unit==2?ve=be[0]*L:ve=w(be[0],b,L,M)-w(0,b,L,M),Ve=Um(x,A,w,b,L,M,Ve),ye=Ve-ve+P}else Ve=Um(x,A,w,b,L,M,Ve),ye=Ve*o+P,ve=Ve-ye;ye<1&&(ye=0),Je>=ve/2&&(Je=0),ye<5&&(z=Wm);let Rt=ye>0,cn=Ve-ye-(Rt?Je:0);ve=z(ku(cn,X,B)),fe=(F==0?ve/2:F==q?0:ve)-F*q*((F==0?P/2:0)+(Rt?Je/2:0));let dt={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},Pt=Ne?null:new Path2D,At=null;if(re!=null)At=m.data[re.series[1]];else{let{y0:be,y1:je}=c;be!=null&&je!=null&&(A=je.values(m,g,v,f),At=be.values(m,g,v,f))}let pt=D*ve,k=ne*ve;for(let be=q==1?v:f;be>=v&&be<=f;be+=q){let je=A[be];if(je==null)continue;if(At!=null){let Y=At[be]??0;if(je-Y==0)continue;me=_(Y,C,R,U)}let ht=b.distr!=2||c!=null?x[be]:be,Ae=w(ht,b,L,M),Vt=_(It(je,Q),C,R,U),We=z(Ae-fe),Ze=z(Zn(Vt,me)),I=z(Ni(Vt,me)),S=Ze-I;if(je!=null){let Y=je<0?k:pt,de=je<0?pt:k;Ne?(Je>0&&pe[be]!=null&&W(Xe.get(pe[be]),We,I+ci(Je/2),ve,Zn(0,S-Je),Y,de),qe[be]!=null&&W(Qe.get(qe[be]),We,I+ci(Je/2),ve,Zn(0,S-Je),Y,de)):W(Pt,We,I+ci(Je/2),ve,Zn(0,S-Je),Y,de),$(m,g,be,We-Je/2,I,ve+Je,S)}}return Je>0?dt.stroke=Ne?Xe:Pt:Ne||(dt._fill=p.width==0?p._fill:p._stroke??p._fill,dt.width=0),dt.fill=Ne?Qe:Pt,dt})}function pv(n,e){let t=It(e?.alignGaps,0);return(i,s,r,o)=>Mr(i,s,(a,l,c,h,d,u,m,g,v,f,p)=>{[r,o]=kl(c,r,o);let x=a.pxRound,A=D=>x(u(D,h,f,g)),b=D=>x(m(D,d,p,v)),C,w,_;h.ori==0?(C=Wl,_=ao,w=_g):(C=Xl,_=lo,w=yg);let M=h.dir*(h.ori==0?1:-1),U=A(l[M==1?r:o]),L=U,R=[],z=[];for(let D=M==1?r:o;D>=r&&D<=o;D+=M)if(c[D]!=null){let q=l[D],W=A(q);R.push(L=W),z.push(b(c[D]))}let F={stroke:n(R,z,C,_,w,x),fill:null,clip:null,band:null,gaps:null,flags:ro},P=F.stroke,[B,X]=nd(i,s);if(a.fill!=null||B!=0){let D=F.fill=new Path2D(P),ne=a.fillTo(i,s,a.min,a.max,B),q=b(ne);_(D,L,q),_(D,U,q)}if(!a.spanGaps){let D=[];D.push(...id(l,c,r,o,M,A,t)),F.gaps=D=a.gaps(i,s,r,o,D),F.clip=Vl(D,h.ori,g,v,f,p)}return X!=0&&(F.band=X==2?[gs(i,s,r,o,P,-1),gs(i,s,r,o,P,1)]:gs(i,s,r,o,P,X)),F})}function mv(n){return pv(gv,n)}function gv(n,e,t,i,s,r){let o=n.length;if(o<2)return null;let a=new Path2D;if(t(a,n[0],e[0]),o==2)i(a,n[1],e[1]);else{let l=Array(o),c=Array(o-1),h=Array(o-1),d=Array(o-1);for(let u=0;u<o-1;u++)h[u]=e[u+1]-e[u],d[u]=n[u+1]-n[u],c[u]=h[u]/d[u];l[0]=c[0];for(let u=1;u<o-1;u++)c[u]===0||c[u-1]===0||c[u-1]>0!=c[u]>0?l[u]=0:(l[u]=3*(d[u-1]+d[u])/((2*d[u]+d[u-1])/c[u-1]+(d[u]+2*d[u-1])/c[u]),isFinite(l[u])||(l[u]=0));l[o-1]=c[o-2];for(let u=0;u<o-1;u++)s(a,n[u]+d[u]/3,e[u]+l[u]*d[u]/3,n[u+1]-d[u]/3,e[u+1]-l[u+1]*d[u]/3,n[u+1],e[u+1])}return a}var Vu=new Set;function Om(){for(let n of Vu)n.syncRect(!0)}oo&&(br(Ky,to,Om),br(Jy,to,Om,!0),br(Ol,to,()=>{Pn.pxRatio=Dt}));var _v=bg(),yv=xg();function Fm(n,e,t,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((r,o)=>Wu(r,o,e,t))}function xv(n,e){return n.map((t,i)=>i==0?{}:yn({},e,t))}function Wu(n,e,t,i){return yn({},e==0?t:i,n)}function Sg(n,e,t){return e==null?io:[e,t]}var vv=Sg;function bv(n,e,t){return e==null?io:Fl(e,t,Zu,!0)}function Mg(n,e,t,i){return e==null?io:zl(e,t,n.scales[i].log,!1)}var Sv=Mg;function wg(n,e,t,i){return e==null?io:Yu(e,t,n.scales[i].log,!1)}var Mv=wg;function wv(n,e,t,i,s){let r=Zn(mm(n),mm(e)),o=e-n,a=Li(s/i*o,t);do{let l=t[a],c=i*l/o;if(c>=s&&r+(l<5?Xs.get(l):0)<=17)return[l,c]}while(++a<t.length);return[0,0]}function Bm(n){let e,t;return n=n.replace(/(\d+)px/,(i,s)=>(e=bn((t=+s)*Dt))+"px"),[n,e,t]}function Ev(n){n.show&&[n.font,n.labelFont].forEach(e=>{let t=Xt(e[2]*Dt,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Pn(n,e,t){let i={mode:It(n.mode,1)},s=i.mode;function r(y,E,N,O){let V=E.valToPct(y);return O+N*(E.dir==-1?1-V:V)}function o(y,E,N,O){let V=E.valToPct(y);return O+N*(E.dir==-1?V:1-V)}function a(y,E,N,O){return E.ori==0?r(y,E,N,O):o(y,E,N,O)}i.valToPosH=r,i.valToPosV=o;let l=!1;i.status=0;let c=i.root=Mi(Ly);if(n.id!=null&&(c.id=n.id),li(c,n.class),n.title){let y=Mi(Uy,c);y.textContent=n.title}let h=Pi("canvas"),d=i.ctx=h.getContext("2d"),u=Mi(Oy,c);br("click",u,y=>{y.target===g&&(qt!=Vr||Qt!=Wr)&&Un.click(i,y)},!0);let m=i.under=Mi(Fy,u);u.appendChild(h);let g=i.over=Mi(By,u);n=so(n);let v=+It(n.pxAlign,1),f=Dm(v);(n.plugins||[]).forEach(y=>{y.opts&&(n=y.opts(i,n)||n)});let p=n.ms||.001,x=i.series=s==1?Fm(n.series||[],Am,Lm,!1):xv(n.series||[null],Pm),A=i.axes=Fm(n.axes||[],Tm,Cm,!0),b=i.scales={},C=i.bands=n.bands||[];C.forEach(y=>{y.fill=Et(y.fill||null),y.dir=It(y.dir,-1)});let w=s==2?x[1].facets[0].scale:x[0].scale,_={axes:hs,series:xt},M=(n.drawOrder||["axes","series"]).map(y=>_[y]);function U(y){let E=y.distr==3?N=>ms(N>0?N:y.clamp(i,N,y.min,y.max,y.key)):y.distr==4?N=>Pu(N,y.asinh):y.distr==100?N=>y.fwd(N):N=>N;return N=>{let O=E(N),{_min:V,_max:j}=y,he=j-V;return(O-V)/he}}function L(y){let E=b[y];if(E==null){let N=(n.scales||fa)[y]||fa;if(N.from!=null){L(N.from);let O=yn({},b[N.from],N,{key:y});O.valToPct=U(O),b[y]=O}else{E=b[y]=yn({},y==w?dg:av,N),E.key=y;let O=E.time,V=E.range,j=Ws(V);if((y!=w||s==2&&!O)&&(j&&(V[0]==null||V[1]==null)&&(V={min:V[0]==null?dm:{mode:1,hard:V[0],soft:V[0]},max:V[1]==null?dm:{mode:1,hard:V[1],soft:V[1]}},j=!1),!j&&Hl(V))){let he=V;V=(ge,Ee,Oe)=>Ee==null?io:Fl(Ee,Oe,he)}E.range=Et(V||(O?vv:y==w?E.distr==3?Sv:E.distr==4?Mv:Sg:E.distr==3?Mg:E.distr==4?wg:bv)),E.auto=Et(j?!1:E.auto),E.clamp=Et(E.clamp||ov),E._min=E._max=null,E.valToPct=U(E)}}}L("x"),L("y"),s==1&&x.forEach(y=>{L(y.scale)}),A.forEach(y=>{L(y.scale)});for(let y in n.scales)L(y);let R=b[w],z=R.distr,F,P;R.ori==0?(li(c,Ny),F=r,P=o):(li(c,Dy),F=o,P=r);let B={};for(let y in b){let E=b[y];(E.min!=null||E.max!=null)&&(B[y]={min:E.min,max:E.max},E.min=E.max=null)}let X=n.tzDate||(y=>new Date(bn(y/p))),D=n.fmtDate||ju,ne=p==1?Nx(X):Ox(X),q=Mm(X,Sm(p==1?Lx:Ux,D)),W=Em(X,wm(Bx,D)),$=[],re=i.legend=yn({},Gx,n.legend),le=i.cursor=yn({},qx,{drag:{y:s==2}},n.cursor),Q=re.show,me=le.show,fe=re.markers;re.idxs=$,fe.width=Et(fe.width),fe.dash=Et(fe.dash),fe.stroke=Et(fe.stroke),fe.fill=Et(fe.fill);let ve,ye,Ve,Je=[],Ne=[],qe,Qe=!1,pe={};if(re.live){let y=x[1]?x[1].values:null;Qe=y!=null,qe=Qe?y(i,1,0):{_:0};for(let E in qe)pe[E]=$u}if(Q)if(ve=Pi("table",Wy,c),Ve=Pi("tbody",null,ve),re.mount(i,ve),Qe){ye=Pi("thead",null,ve,Ve);let y=Pi("tr",null,ye);Pi("th",null,y);for(var Xe in qe)Pi("th",Qp,y).textContent=Xe}else li(ve,$y),re.live&&li(ve,Xy);let et={show:!0},Gt={show:!1};function Rt(y,E){if(E==0&&(Qe||!re.live||s==2))return io;let N=[],O=Pi("tr",qy,Ve,Ve.childNodes[E]);li(O,y.class),y.show||li(O,vr);let V=Pi("th",null,O);if(fe.show){let ge=Mi(Yy,V);if(E>0){let Ee=fe.width(i,E);Ee&&(ge.style.border=Ee+"px "+fe.dash(i,E)+" "+fe.stroke(i,E)),ge.style.background=fe.fill(i,E)}}let j=Mi(Qp,V);y.label instanceof HTMLElement?j.appendChild(y.label):j.textContent=y.label,E>0&&(fe.show||(j.style.color=y.width>0?fe.stroke(i,E):fe.fill(i,E)),dt("click",V,ge=>{if(le._lock)return;it(ge);let Ee=x.indexOf(y);if((ge.ctrlKey||ge.metaKey)!=re.isolate){let Oe=x.some((Fe,ke)=>ke>0&&ke!=Ee&&Fe.show);x.forEach((Fe,ke)=>{ke>0&&$i(ke,Oe?ke==Ee?et:Gt:et,!0,mn.setSeries)})}else $i(Ee,{show:!y.show},!0,mn.setSeries)},!1),st&&dt(im,V,ge=>{le._lock||(it(ge),$i(x.indexOf(y),$r,!0,mn.setSeries))},!1));for(var he in qe){let ge=Pi("td",Zy,O);ge.textContent="--",N.push(ge)}return[O,N]}let cn=new Map;function dt(y,E,N,O=!0){let V=cn.get(E)||{},j=le.bind[y](i,E,N,O);j&&(br(y,E,V[y]=j),cn.set(E,V))}function Pt(y,E,N){let O=cn.get(E)||{};for(let V in O)(y==null||V==y)&&(Bu(V,E,O[V]),delete O[V]);y==null&&cn.delete(E)}let At=0,pt=0,k=0,be=0,je=0,ht=0,Ae=je,Vt=ht,We=k,Ze=be,I=0,S=0,Y=0,de=0;i.bbox={};let ce=!1,Me=!1,we=!1,ie=!1,oe=!1,_e=!1;function G(y,E,N){(N||y!=i.width||E!=i.height)&&ae(y,E),mt(!1),we=!0,Me=!0,Bn()}function ae(y,E){i.width=At=k=y,i.height=pt=be=E,je=ht=0,Te(),$e();let N=i.bbox;I=N.left=yr(je*Dt,.5),S=N.top=yr(ht*Dt,.5),Y=N.width=yr(k*Dt,.5),de=N.height=yr(be*Dt,.5)}let se=3;function Re(){let y=!1,E=0;for(;!y;){E++;let N=zr(E),O=Xi(E);y=E==se||N&&O,y||(ae(i.width,i.height),Me=!0)}}function Se({width:y,height:E}){G(y,E)}i.setSize=Se;function Te(){let y=!1,E=!1,N=!1,O=!1;A.forEach((V,j)=>{if(V.show&&V._show){let{side:he,_size:ge}=V,Ee=he%2,Oe=V.label!=null?V.labelSize:0,Fe=ge+Oe;Fe>0&&(Ee?(k-=Fe,he==3?(je+=Fe,O=!0):N=!0):(be-=Fe,he==0?(ht+=Fe,y=!0):E=!0))}}),Vi[0]=y,Vi[1]=N,Vi[2]=E,Vi[3]=O,k-=Ai[1]+Ai[3],je+=Ai[3],be-=Ai[2]+Ai[0],ht+=Ai[0]}function $e(){let y=je+k,E=ht+be,N=je,O=ht;function V(j,he){switch(j){case 1:return y+=he,y-he;case 2:return E+=he,E-he;case 3:return N-=he,N+he;case 0:return O-=he,O+he}}A.forEach((j,he)=>{if(j.show&&j._show){let ge=j.side;j._pos=V(ge,j._size),j.label!=null&&(j._lpos=V(ge,j.labelSize))}})}if(le.dataIdx==null){let y=le.hover,E=y.skip=new Set(y.skip??[]);E.add(void 0);let N=y.prox=Et(y.prox),O=y.bias??=0;le.dataIdx=(V,j,he,ge)=>{if(j==0)return he;let Ee=he,Oe=N(V,j,he,ge)??Wt,Fe=Oe>=0&&Oe<Wt,ke=R.ori==0?k:be,lt=le.left,Lt=e[0],Ct=e[j];if(E.has(Ct[he])){Ee=null;let St=null,nt=null,Ye;if(O==0||O==-1)for(Ye=he;St==null&&Ye-- >0;)E.has(Ct[Ye])||(St=Ye);if(O==0||O==1)for(Ye=he;nt==null&&Ye++<Ct.length;)E.has(Ct[Ye])||(nt=Ye);if(St!=null||nt!=null)if(Fe){let Zt=St==null?-1/0:F(Lt[St],R,ke,0),an=nt==null?1/0:F(Lt[nt],R,ke,0),Cn=lt-Zt,Ht=an-lt;Cn<=Ht?Cn<=Oe&&(Ee=St):Ht<=Oe&&(Ee=nt)}else Ee=nt==null?St:St==null?nt:he-St<=nt-he?St:nt}else Fe&&Sn(lt-F(Lt[he],R,ke,0))>Oe&&(Ee=null);return Ee}}let it=y=>{le.event=y};le.idxs=$,le._lock=!1;let ue=le.points;ue.show=Et(ue.show),ue.size=Et(ue.size),ue.stroke=Et(ue.stroke),ue.width=Et(ue.width),ue.fill=Et(ue.fill);let ze=i.focus=yn({},n.focus||{alpha:.3},le.focus),st=ze.prox>=0,Pe=st&&ue.one,ft=[],$t=[],Wn=[];function Ho(y,E){let N=ue.show(i,E);if(N instanceof HTMLElement)return li(N,Vy),li(N,y.class),ji(N,-10,-10,k,be),g.insertBefore(N,ft[E]),N}function Fr(y,E){if(s==1||E>0){let N=s==1&&b[y.scale].time,O=y.value;y.value=N?ym(O)?Em(X,wm(O,D)):O||W:O||iv,y.label=y.label||(N?Zx:Yx)}if(Pe||E>0){y.width=y.width==null?1:y.width,y.paths=y.paths||_v||ax,y.fillTo=Et(y.fillTo||lv),y.pxAlign=+It(y.pxAlign,v),y.pxRound=Dm(y.pxAlign),y.stroke=Et(y.stroke||null),y.fill=Et(y.fill||null),y._stroke=y._fill=y._paths=y._focus=null;let N=sv(Zn(1,y.width),1),O=y.points=yn({},{size:N,width:Zn(1,N*.2),stroke:y.stroke,space:N*2,paths:yv,_stroke:null,_fill:null},y.points);O.show=Et(O.show),O.filter=Et(O.filter),O.fill=Et(O.fill),O.stroke=Et(O.stroke),O.paths=Et(O.paths),O.pxAlign=y.pxAlign}if(Q){let N=Rt(y,E);Je.splice(E,0,N[0]),Ne.splice(E,0,N[1]),re.values.push(null)}if(me){$.splice(E,0,null);let N=null;Pe?E==0&&(N=Ho(y,E)):E>0&&(N=Ho(y,E)),ft.splice(E,0,N),$t.splice(E,0,0),Wn.splice(E,0,0)}Rn("addSeries",E)}function jh(y,E){E=E??x.length,y=s==1?Wu(y,E,Am,Lm):Wu(y,E,{},Pm),x.splice(E,0,y),Fr(x[E],E)}i.addSeries=jh;function sl(y){if(x.splice(y,1),Q){re.values.splice(y,1),Ne.splice(y,1);let E=Je.splice(y,1)[0];Pt(null,E.firstChild),E.remove()}me&&($.splice(y,1),ft.splice(y,1)[0].remove(),$t.splice(y,1),Wn.splice(y,1)),Rn("delSeries",y)}i.delSeries=sl;let Vi=[!1,!1,!1,!1];function as(y,E){if(y._show=y.show,y.show){let N=y.side%2,O=b[y.scale];O==null&&(y.scale=N?x[1].scale:w,O=b[y.scale]);let V=O.time;y.size=Et(y.size),y.space=Et(y.space),y.rotate=Et(y.rotate),Ws(y.incrs)&&y.incrs.forEach(he=>{!Xs.has(he)&&Xs.set(he,qm(he))}),y.incrs=Et(y.incrs||(O.distr==2?Cx:V?p==1?Px:Dx:xr)),y.splits=Et(y.splits||(V&&O.distr==1?ne:O.distr==3?zu:O.distr==4?jx:Jx)),y.stroke=Et(y.stroke),y.grid.stroke=Et(y.grid.stroke),y.ticks.stroke=Et(y.ticks.stroke),y.border.stroke=Et(y.border.stroke);let j=y.values;y.values=Ws(j)&&!Ws(j[0])?Et(j):V?Ws(j)?Mm(X,Sm(j,D)):ym(j)?Fx(X,j):j||q:j||Kx,y.filter=Et(y.filter||(O.distr>=3&&O.log==10?tv:O.distr==3&&O.log==2?nv:Xm)),y.font=Bm(y.font),y.labelFont=Bm(y.labelFont),y._size=y.size(i,null,E,0),y._space=y._rotate=y._incrs=y._found=y._splits=y._values=null,y._size>0&&(Vi[E]=!0,y._el=Mi(ky,u))}}function ls(y,E,N,O){let[V,j,he,ge]=N,Ee=E%2,Oe=0;return Ee==0&&(ge||j)&&(Oe=E==0&&!V||E==2&&!he?bn(Tm.size/3):0),Ee==1&&(V||he)&&(Oe=E==1&&!j||E==3&&!ge?bn(Cm.size/2):0),Oe}let Vo=i.padding=(n.padding||[ls,ls,ls,ls]).map(y=>Et(It(y,ls))),Ai=i._padding=Vo.map((y,E)=>y(i,E,Vi,0)),rn,hn=null,un=null,Wi=s==1?x[0].idxs:null,si=null,Is=!1;function Wo(y,E){if(e=y??[],i.data=i._data=e,s==2){rn=0;for(let N=1;N<x.length;N++)rn+=e[N][0].length}else{e.length==0&&(i.data=i._data=e=[[]]),si=e[0],rn=si.length;let N=e;if(z==2){N=e.slice();let O=N[0]=Array(rn);for(let V=0;V<rn;V++)O[V]=V}i._data=e=N}if(mt(!0),Rn("setData"),z==2&&(we=!0),E!==!1){let N=R;N.auto(i,Is)?Xo():Ns(w,N.min,N.max),ie=ie||le.left>=0,_e=!0,Bn()}}i.setData=Wo;function Xo(){Is=!0;let y,E;s==1&&(rn>0?(hn=Wi[0]=0,un=Wi[1]=rn-1,y=e[0][hn],E=e[0][un],z==2?(y=hn,E=un):y==E&&(z==3?[y,E]=zl(y,y,R.log,!1):z==4?[y,E]=Yu(y,y,R.log,!1):R.time?E=y+bn(86400/p):[y,E]=Fl(y,E,Zu,!0))):(hn=Wi[0]=y=null,un=Wi[1]=E=null)),Ns(w,y,E)}let Br,Ps,kr,T,H,ee,Z,K,Ce,Le;function Ie(y,E,N,O,V,j){y??=tm,N??=Ju,O??="butt",V??=tm,j??="round",y!=Br&&(d.strokeStyle=Br=y),V!=Ps&&(d.fillStyle=Ps=V),E!=kr&&(d.lineWidth=kr=E),j!=H&&(d.lineJoin=H=j),O!=ee&&(d.lineCap=ee=O),N!=T&&d.setLineDash(T=N)}function De(y,E,N,O){E!=Ps&&(d.fillStyle=Ps=E),y!=Z&&(d.font=Z=y),N!=K&&(d.textAlign=K=N),O!=Ce&&(d.textBaseline=Ce=O)}function He(y,E,N,O,V=0){if(O.length>0&&y.auto(i,Is)&&(E==null||E.min==null)){let j=It(hn,0),he=It(un,O.length-1),ge=N.min==null?tx(O,j,he,V,y.distr==3):[N.min,N.max];y.min=Ni(y.min,N.min=ge[0]),y.max=Zn(y.max,N.max=ge[1])}}let rt={min:null,max:null};function yt(){for(let O in b){let V=b[O];B[O]==null&&(V.min==null||B[w]!=null&&V.auto(i,Is))&&(B[O]=rt)}for(let O in b){let V=b[O];B[O]==null&&V.from!=null&&B[V.from]!=null&&(B[O]=rt)}B[w]!=null&&mt(!0);let y={};for(let O in B){let V=B[O];if(V!=null){let j=y[O]=so(b[O],hx);if(V.min!=null)yn(j,V);else if(O!=w||s==2)if(rn==0&&j.from==null){let he=j.range(i,null,null,O);j.min=he[0],j.max=he[1]}else j.min=Wt,j.max=-Wt}}if(rn>0){x.forEach((O,V)=>{if(s==1){let j=O.scale,he=B[j];if(he==null)return;let ge=y[j];if(V==0){let Ee=ge.range(i,ge.min,ge.max,j);ge.min=Ee[0],ge.max=Ee[1],hn=Li(ge.min,e[0]),un=Li(ge.max,e[0]),un-hn>1&&(e[0][hn]<ge.min&&hn++,e[0][un]>ge.max&&un--),O.min=si[hn],O.max=si[un]}else O.show&&O.auto&&He(ge,he,O,e[V],O.sorted);O.idxs[0]=hn,O.idxs[1]=un}else if(V>0&&O.show&&O.auto){let[j,he]=O.facets,ge=j.scale,Ee=he.scale,[Oe,Fe]=e[V],ke=y[ge],lt=y[Ee];ke!=null&&He(ke,B[ge],j,Oe,j.sorted),lt!=null&&He(lt,B[Ee],he,Fe,he.sorted),O.min=he.min,O.max=he.max}});for(let O in y){let V=y[O],j=B[O];if(V.from==null&&(j==null||j.min==null)){let he=V.range(i,V.min==Wt?null:V.min,V.max==-Wt?null:V.max,O);V.min=he[0],V.max=he[1]}}}for(let O in y){let V=y[O];if(V.from!=null){let j=y[V.from];if(j.min==null)V.min=V.max=null;else{let he=V.range(i,j.min,j.max,O);V.min=he[0],V.max=he[1]}}}let E={},N=!1;for(let O in y){let V=y[O],j=b[O];if(j.min!=V.min||j.max!=V.max){j.min=V.min,j.max=V.max;let he=j.distr;j._min=he==3?ms(j.min):he==4?Pu(j.min,j.asinh):he==100?j.fwd(j.min):j.min,j._max=he==3?ms(j.max):he==4?Pu(j.max,j.asinh):he==100?j.fwd(j.max):j.max,E[O]=N=!0}}if(N){x.forEach((O,V)=>{s==2?V>0&&E.y&&(O._paths=null):E[O.scale]&&(O._paths=null)});for(let O in E)we=!0,Rn("setScale",O);me&&le.left>=0&&(ie=_e=!0)}for(let O in B)B[O]=null}function Ge(y){let E=ku(hn-1,0,rn-1),N=ku(un+1,0,rn-1);for(;y[E]==null&&E>0;)E--;for(;y[N]==null&&N<rn-1;)N++;return[E,N]}function xt(){if(rn>0){let y=x.some(E=>E._focus)&&Le!=ze.alpha;y&&(d.globalAlpha=Le=ze.alpha),x.forEach((E,N)=>{if(N>0&&E.show&&(tn(N,!1),tn(N,!0),E._paths==null)){let O=Le;Le!=E.alpha&&(d.globalAlpha=Le=E.alpha);let V=s==2?[0,e[N][0].length-1]:Ge(e[N]);E._paths=E.paths(i,N,V[0],V[1]),Le!=O&&(d.globalAlpha=Le=O)}}),x.forEach((E,N)=>{if(N>0&&E.show){let O=Le;Le!=E.alpha&&(d.globalAlpha=Le=E.alpha),E._paths!=null&&Bt(N,!1);{let V=E._paths!=null?E._paths.gaps:null,j=E.points.show(i,N,hn,un,V),he=E.points.filter(i,N,j,V);(j||he)&&(E.points._paths=E.points.paths(i,N,hn,un,he),Bt(N,!0))}Le!=O&&(d.globalAlpha=Le=O),Rn("drawSeries",N)}}),y&&(d.globalAlpha=Le=1)}}function tn(y,E){let N=E?x[y].points:x[y];N._stroke=N.stroke(i,y),N._fill=N.fill(i,y)}function Bt(y,E){let N=E?x[y].points:x[y],{stroke:O,fill:V,clip:j,flags:he,_stroke:ge=N._stroke,_fill:Ee=N._fill,_width:Oe=N.width}=N._paths;Oe=Xt(Oe*Dt,3);let Fe=null,ke=Oe%2/2;E&&Ee==null&&(Ee=Oe>0?"#fff":ge);let lt=N.pxAlign==1&&ke>0;if(lt&&d.translate(ke,ke),!E){let Lt=I-Oe/2,Ct=S-Oe/2,St=Y+Oe,nt=de+Oe;Fe=new Path2D,Fe.rect(Lt,Ct,St,nt)}E?Be(ge,Oe,N.dash,N.cap,Ee,O,V,he,j):kt(y,ge,Oe,N.dash,N.cap,Ee,O,V,he,Fe,j),lt&&d.translate(-ke,-ke)}function kt(y,E,N,O,V,j,he,ge,Ee,Oe,Fe){let ke=!1;Ee!=0&&C.forEach((lt,Lt)=>{if(lt.series[0]==y){let Ct=x[lt.series[1]],St=e[lt.series[1]],nt=(Ct._paths||fa).band;Ws(nt)&&(nt=lt.dir==1?nt[0]:nt[1]);let Ye,Zt=null;Ct.show&&nt&&ix(St,hn,un)?(Zt=lt.fill(i,Lt)||j,Ye=Ct._paths.clip):nt=null,Be(E,N,O,V,Zt,he,ge,Ee,Oe,Fe,Ye,nt),ke=!0}}),ke||Be(E,N,O,V,j,he,ge,Ee,Oe,Fe)}let vn=ro|Hu;function Be(y,E,N,O,V,j,he,ge,Ee,Oe,Fe,ke){Ie(y,E,N,O,V),(Ee||Oe||ke)&&(d.save(),Ee&&d.clip(Ee),Oe&&d.clip(Oe)),ke?(ge&vn)==vn?(d.clip(ke),Fe&&d.clip(Fe),wt(V,he),dn(y,j,E)):ge&Hu?(wt(V,he),d.clip(ke),dn(y,j,E)):ge&ro&&(d.save(),d.clip(ke),Fe&&d.clip(Fe),wt(V,he),d.restore(),dn(y,j,E)):(wt(V,he),dn(y,j,E)),(Ee||Oe||ke)&&d.restore()}function dn(y,E,N){N>0&&(E instanceof Map?E.forEach((O,V)=>{d.strokeStyle=Br=V,d.stroke(O)}):E!=null&&y&&d.stroke(E))}function wt(y,E){E instanceof Map?E.forEach((N,O)=>{d.fillStyle=Ps=O,d.fill(N)}):E!=null&&y&&d.fill(E)}function cs(y,E,N,O){let V=A[y],j;if(O<=0)j=[0,0];else{let he=V._space=V.space(i,y,E,N,O),ge=V._incrs=V.incrs(i,y,E,N,O,he);j=wv(E,N,ge,O,he)}return V._found=j}function fn(y,E,N,O,V,j,he,ge,Ee,Oe){let Fe=he%2/2;v==1&&d.translate(Fe,Fe),Ie(ge,he,Ee,Oe,ge),d.beginPath();let ke,lt,Lt,Ct,St=V+(O==0||O==3?-j:j);N==0?(lt=V,Ct=St):(ke=V,Lt=St);for(let nt=0;nt<y.length;nt++)E[nt]!=null&&(N==0?ke=Lt=y[nt]:lt=Ct=y[nt],d.moveTo(ke,lt),d.lineTo(Lt,Ct));d.stroke(),v==1&&d.translate(-Fe,-Fe)}function zr(y){let E=!0;return A.forEach((N,O)=>{if(!N.show)return;let V=b[N.scale];if(V.min==null){N._show&&(E=!1,N._show=!1,mt(!1));return}else N._show||(E=!1,N._show=!0,mt(!1));let j=N.side,he=j%2,{min:ge,max:Ee}=V,[Oe,Fe]=cs(O,ge,Ee,he==0?k:be);if(Fe==0)return;let ke=V.distr==2,lt=N._splits=N.splits(i,O,ge,Ee,Oe,Fe,ke),Lt=V.distr==2?lt.map(Ye=>si[Ye]):lt,Ct=V.distr==2?si[lt[1]]-si[lt[0]]:Oe,St=N._values=N.values(i,N.filter(i,Lt,O,Fe,Ct),O,Fe,Ct);N._rotate=j==2?N.rotate(i,St,O,Fe):0;let nt=N._size;N._size=wi(N.size(i,St,O,y)),nt!=null&&N._size!=nt&&(E=!1)}),E}function Xi(y){let E=!0;return Vo.forEach((N,O)=>{let V=N(i,O,Vi,y);V!=Ai[O]&&(E=!1),Ai[O]=V}),E}function hs(){for(let y=0;y<A.length;y++){let E=A[y];if(!E.show||!E._show)continue;let N=E.side,O=N%2,V,j,he=E.stroke(i,y),ge=N==0||N==3?-1:1,[Ee,Oe]=E._found;if(E.label!=null){let qn=E.labelGap*ge,ai=bn((E._lpos+qn)*Dt);De(E.labelFont[0],he,"center",N==2?"top":em),d.save(),O==1?(V=j=0,d.translate(ai,bn(S+de/2)),d.rotate((N==3?-Ul:Ul)/2)):(V=bn(I+Y/2),j=ai);let dr=Vm(E.label)?E.label(i,y,Ee,Oe):E.label;d.fillText(dr,V,j),d.restore()}if(Oe==0)continue;let Fe=b[E.scale],ke=O==0?Y:de,lt=O==0?I:S,Lt=E._splits,Ct=Fe.distr==2?Lt.map(qn=>si[qn]):Lt,St=Fe.distr==2?si[Lt[1]]-si[Lt[0]]:Ee,nt=E.ticks,Ye=E.border,Zt=nt.show?nt.size:0,an=bn(Zt*Dt),Cn=bn((E.alignTo==2?E._size-Zt-E.gap:E.gap)*Dt),Ht=E._rotate*-Ul/180,ln=f(E._pos*Dt),ri=(an+Cn)*ge,$n=ln+ri;j=O==0?$n:0,V=O==1?$n:0;let vi=E.font[0],Ri=E.align==1?Qr:E.align==2?Ru:Ht>0?Qr:Ht<0?Ru:O==0?"center":N==3?Ru:Qr,Yi=Ht||O==1?"middle":N==2?"top":em;De(vi,he,Ri,Yi);let oi=E.font[1]*E.lineGap,bi=Lt.map(qn=>f(a(qn,Fe,ke,lt))),Ci=E._values;for(let qn=0;qn<Ci.length;qn++){let ai=Ci[qn];if(ai!=null){O==0?V=bi[qn]:j=bi[qn],ai=""+ai;let dr=ai.indexOf(`
`)==-1?[ai]:ai.split(/\n/gm);for(let Yn=0;Yn<dr.length;Yn++){let np=dr[Yn];Ht?(d.save(),d.translate(V,j+Yn*oi),d.rotate(Ht),d.fillText(np,0,0),d.restore()):d.fillText(np,V,j+Yn*oi)}}}nt.show&&fn(bi,nt.filter(i,Ct,y,Oe,St),O,N,ln,an,Xt(nt.width*Dt,3),nt.stroke(i,y),nt.dash,nt.cap);let Zi=E.grid;Zi.show&&fn(bi,Zi.filter(i,Ct,y,Oe,St),O,O==0?2:1,O==0?S:I,O==0?de:Y,Xt(Zi.width*Dt,3),Zi.stroke(i,y),Zi.dash,Zi.cap),Ye.show&&fn([ln],[1],O==0?1:0,O==0?1:2,O==1?S:I,O==1?de:Y,Xt(Ye.width*Dt,3),Ye.stroke(i,y),Ye.dash,Ye.cap)}Rn("drawAxes")}function mt(y){x.forEach((E,N)=>{N>0&&(E._paths=null,y&&(s==1?(E.min=null,E.max=null):E.facets.forEach(O=>{O.min=null,O.max=null})))})}let on=!1,Xn=!1,zt=[];function pn(){Xn=!1;for(let y=0;y<zt.length;y++)Rn(...zt[y]);zt.length=0}function Bn(){on||(_x(Bf),on=!0)}function rl(y,E=!1){on=!0,Xn=E,y(i),Bf(),E&&zt.length>0&&queueMicrotask(pn)}i.batch=rl;function Bf(){if(ce&&(yt(),ce=!1),we&&(Re(),we=!1),Me){if(Jt(m,Qr,je),Jt(m,"top",ht),Jt(m,ca,k),Jt(m,ha,be),Jt(g,Qr,je),Jt(g,"top",ht),Jt(g,ca,k),Jt(g,ha,be),Jt(u,ca,At),Jt(u,ha,pt),h.width=bn(At*Dt),h.height=bn(pt*Dt),A.forEach(({_el:y,_show:E,_size:N,_pos:O,side:V})=>{if(y!=null)if(E){let j=V===3||V===0?N:0,he=V%2==1;Jt(y,he?"left":"top",O-j),Jt(y,he?"width":"height",N),Jt(y,he?"top":"left",he?ht:je),Jt(y,he?"height":"width",he?be:k),Fu(y,vr)}else li(y,vr)}),Br=Ps=kr=H=ee=Z=K=Ce=T=null,Le=1,Yo(!0),je!=Ae||ht!=Vt||k!=We||be!=Ze){mt(!1);let y=k/We,E=be/Ze;if(me&&!ie&&le.left>=0){le.left*=y,le.top*=E,Gr&&ji(Gr,bn(le.left),0,k,be),Hr&&ji(Hr,0,bn(le.top),k,be);for(let N=0;N<ft.length;N++){let O=ft[N];O!=null&&($t[N]*=y,Wn[N]*=E,ji(O,wi($t[N]),wi(Wn[N]),k,be))}}if(Yt.show&&!oe&&Yt.left>=0&&Yt.width>0){Yt.left*=y,Yt.width*=y,Yt.top*=E,Yt.height*=E;for(let N in su)Jt(Xr,N,Yt[N])}Ae=je,Vt=ht,We=k,Ze=be}Rn("setSize"),Me=!1}At>0&&pt>0&&(d.clearRect(0,0,h.width,h.height),Rn("drawClear"),M.forEach(y=>y()),Rn("draw")),Yt.show&&oe&&(ol(Yt),oe=!1),me&&ie&&(ur(null,!0,!1),ie=!1),re.show&&re.live&&_e&&(nu(),_e=!1),l||(l=!0,i.status=1,Rn("ready")),Is=!1,on=!1}i.redraw=(y,E)=>{we=E||!1,y!==!1?Ns(w,R.min,R.max):Bn()};function Qh(y,E){let N=b[y];if(N.from==null){if(rn==0){let O=N.range(i,E.min,E.max,y);E.min=O[0],E.max=O[1]}if(E.min>E.max){let O=E.min;E.min=E.max,E.max=O}if(rn>1&&E.min!=null&&E.max!=null&&E.max-E.min<1e-16)return;y==w&&N.distr==2&&rn>0&&(E.min=Li(E.min,e[0]),E.max=Li(E.max,e[0]),E.min==E.max&&E.max++),B[y]=E,ce=!0,Bn()}}i.setScale=Qh;let eu,tu,Gr,Hr,kf,zf,Vr,Wr,Gf,Hf,qt,Qt,Ls=!1,Un=le.drag,Tn=Un.x,An=Un.y;me&&(le.x&&(eu=Mi(Gy,g)),le.y&&(tu=Mi(Hy,g)),R.ori==0?(Gr=eu,Hr=tu):(Gr=tu,Hr=eu),qt=le.left,Qt=le.top);let Yt=i.select=yn({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),Xr=Yt.show?Mi(zy,Yt.over?g:m):null;function ol(y,E){if(Yt.show){for(let N in y)Yt[N]=y[N],N in su&&Jt(Xr,N,y[N]);E!==!1&&Rn("setSelect")}}i.setSelect=ol;function O_(y){if(x[y].show)Q&&Fu(Je[y],vr);else if(Q&&li(Je[y],vr),me){let N=Pe?ft[0]:ft[y];N!=null&&ji(N,-10,-10,k,be)}}function Ns(y,E,N){Qh(y,{min:E,max:N})}function $i(y,E,N,O){E.focus!=null&&G_(y),E.show!=null&&x.forEach((V,j)=>{j>0&&(y==j||y==null)&&(V.show=E.show,O_(j),s==2?(Ns(V.facets[0].scale,null,null),Ns(V.facets[1].scale,null,null)):Ns(V.scale,null,null),Bn())}),N!==!1&&Rn("setSeries",y,E),O&&Zo("setSeries",i,y,E)}i.setSeries=$i;function F_(y,E){yn(C[y],E)}function B_(y,E){y.fill=Et(y.fill||null),y.dir=It(y.dir,-1),E=E??C.length,C.splice(E,0,y)}function k_(y){y==null?C.length=0:C.splice(y,1)}i.addBand=B_,i.setBand=F_,i.delBand=k_;function z_(y,E){x[y].alpha=E,me&&ft[y]!=null&&(ft[y].style.opacity=E),Q&&Je[y]&&(Je[y].style.opacity=E)}let us,Ds,hr,$r={focus:!0};function G_(y){if(y!=hr){let E=y==null,N=ze.alpha!=1;x.forEach((O,V)=>{if(s==1||V>0){let j=E||V==0||V==y;O._focus=E?null:j,N&&z_(V,j?1:ze.alpha)}}),hr=y,N&&Bn()}}Q&&st&&dt(sm,ve,y=>{le._lock||(it(y),hr!=null&&$i(null,$r,!0,mn.setSeries))});function qi(y,E,N){let O=b[E];N&&(y=y/Dt-(O.ori==1?ht:je));let V=k;O.ori==1&&(V=be,y=V-y),O.dir==-1&&(y=V-y);let j=O._min,he=O._max,ge=y/V,Ee=j+(he-j)*ge,Oe=O.distr;return Oe==3?no(10,Ee):Oe==4?rx(Ee,O.asinh):Oe==100?O.bwd(Ee):Ee}function H_(y,E){let N=qi(y,w,E);return Li(N,e[0],hn,un)}i.valToIdx=y=>Li(y,e[0]),i.posToIdx=H_,i.posToVal=qi,i.valToPos=(y,E,N)=>b[E].ori==0?r(y,b[E],N?Y:k,N?I:0):o(y,b[E],N?de:be,N?S:0),i.setCursor=(y,E,N)=>{qt=y.left,Qt=y.top,ur(null,E,N)};function Vf(y,E){Jt(Xr,Qr,Yt.left=y),Jt(Xr,ca,Yt.width=E)}function Wf(y,E){Jt(Xr,"top",Yt.top=y),Jt(Xr,ha,Yt.height=E)}let $o=R.ori==0?Vf:Wf,qo=R.ori==1?Vf:Wf;function V_(){if(Q&&re.live)for(let y=s==2?1:0;y<x.length;y++){if(y==0&&Qe)continue;let E=re.values[y],N=0;for(let O in E)Ne[y][N++].firstChild.nodeValue=E[O]}}function nu(y,E){if(y!=null&&(y.idxs?y.idxs.forEach((N,O)=>{$[O]=N}):cx(y.idx)||$.fill(y.idx),re.idx=$[0]),Q&&re.live){for(let N=0;N<x.length;N++)(N>0||s==1&&!Qe)&&W_(N,$[N]);V_()}_e=!1,E!==!1&&Rn("setLegend")}i.setLegend=nu;function W_(y,E){let N=x[y],O=y==0&&z==2?si:e[y],V;Qe?V=N.values(i,y,E)??pe:(V=N.value(i,E==null?null:O[E],y,E),V=V==null?pe:{_:V}),re.values[y]=V}function ur(y,E,N){Gf=qt,Hf=Qt,[qt,Qt]=le.move(i,qt,Qt),le.left=qt,le.top=Qt,me&&(Gr&&ji(Gr,bn(qt),0,k,be),Hr&&ji(Hr,0,bn(Qt),k,be));let O,V=hn>un;us=Wt,Ds=null;let j=R.ori==0?k:be,he=R.ori==1?k:be;if(qt<0||rn==0||V){O=le.idx=null;for(let ge=0;ge<x.length;ge++){let Ee=ft[ge];Ee!=null&&ji(Ee,-10,-10,k,be)}st&&$i(null,$r,!0,y==null&&mn.setSeries),re.live&&($.fill(O),_e=!0)}else{let ge,Ee,Oe;s==1&&(ge=R.ori==0?qt:Qt,Ee=qi(ge,w),O=le.idx=Li(Ee,e[0],hn,un),Oe=F(e[0][O],R,j,0));let Fe=-10,ke=-10,lt=0,Lt=0,Ct=!0,St="",nt="";for(let Ye=s==2?1:0;Ye<x.length;Ye++){let Zt=x[Ye],an=$[Ye],Cn=an==null?null:s==1?e[Ye][an]:e[Ye][1][an],Ht=le.dataIdx(i,Ye,O,Ee),ln=Ht==null?null:s==1?e[Ye][Ht]:e[Ye][1][Ht];if(_e=_e||ln!=Cn||Ht!=an,$[Ye]=Ht,Ye>0&&Zt.show){let ri=Ht==null?-10:Ht==O?Oe:F(s==1?e[0][Ht]:e[Ye][0][Ht],R,j,0),$n=ln==null?-10:P(ln,s==1?b[Zt.scale]:b[Zt.facets[1].scale],he,0);if(st&&ln!=null){let vi=R.ori==1?qt:Qt,Ri=Sn(ze.dist(i,Ye,Ht,$n,vi));if(Ri<us){let Yi=ze.bias;if(Yi!=0){let oi=qi(vi,Zt.scale),bi=ln>=0?1:-1,Ci=oi>=0?1:-1;Ci==bi&&(Ci==1?Yi==1?ln>=oi:ln<=oi:Yi==1?ln<=oi:ln>=oi)&&(us=Ri,Ds=Ye)}else us=Ri,Ds=Ye}}if(_e||Pe){let vi,Ri;R.ori==0?(vi=ri,Ri=$n):(vi=$n,Ri=ri);let Yi,oi,bi,Ci,Zi,qn,ai=!0,dr=ue.bbox;if(dr!=null){ai=!1;let Yn=dr(i,Ye);bi=Yn.left,Ci=Yn.top,Yi=Yn.width,oi=Yn.height}else bi=vi,Ci=Ri,Yi=oi=ue.size(i,Ye);if(qn=ue.fill(i,Ye),Zi=ue.stroke(i,Ye),Pe)Ye==Ds&&us<=ze.prox&&(Fe=bi,ke=Ci,lt=Yi,Lt=oi,Ct=ai,St=qn,nt=Zi);else{let Yn=ft[Ye];Yn!=null&&($t[Ye]=bi,Wn[Ye]=Ci,um(Yn,Yi,oi,ai),cm(Yn,qn,Zi),ji(Yn,wi(bi),wi(Ci),k,be))}}}}if(Pe){let Ye=ze.prox,Zt=hr==null?us<=Ye:us>Ye||Ds!=hr;if(_e||Zt){let an=ft[0];an!=null&&($t[0]=Fe,Wn[0]=ke,um(an,lt,Lt,Ct),cm(an,St,nt),ji(an,wi(Fe),wi(ke),k,be))}}}if(Yt.show&&Ls)if(y!=null){let[ge,Ee]=mn.scales,[Oe,Fe]=mn.match,[ke,lt]=y.cursor.sync.scales,Lt=y.cursor.drag;if(Tn=Lt._x,An=Lt._y,Tn||An){let{left:Ct,top:St,width:nt,height:Ye}=y.select,Zt=y.scales[ke].ori,an=y.posToVal,Cn,Ht,ln,ri,$n,vi=ge!=null&&Oe(ge,ke),Ri=Ee!=null&&Fe(Ee,lt);vi&&Tn?(Zt==0?(Cn=Ct,Ht=nt):(Cn=St,Ht=Ye),ln=b[ge],ri=F(an(Cn,ke),ln,j,0),$n=F(an(Cn+Ht,ke),ln,j,0),$o(Ni(ri,$n),Sn($n-ri))):$o(0,j),Ri&&An?(Zt==1?(Cn=Ct,Ht=nt):(Cn=St,Ht=Ye),ln=b[Ee],ri=P(an(Cn,lt),ln,he,0),$n=P(an(Cn+Ht,lt),ln,he,0),qo(Ni(ri,$n),Sn($n-ri))):qo(0,he)}else ru()}else{let ge=Sn(Gf-kf),Ee=Sn(Hf-zf);if(R.ori==1){let lt=ge;ge=Ee,Ee=lt}Tn=Un.x&&ge>=Un.dist,An=Un.y&&Ee>=Un.dist;let Oe=Un.uni;Oe!=null?Tn&&An&&(Tn=ge>=Oe,An=Ee>=Oe,!Tn&&!An&&(Ee>ge?An=!0:Tn=!0)):Un.x&&Un.y&&(Tn||An)&&(Tn=An=!0);let Fe,ke;Tn&&(R.ori==0?(Fe=Vr,ke=qt):(Fe=Wr,ke=Qt),$o(Ni(Fe,ke),Sn(ke-Fe)),An||qo(0,he)),An&&(R.ori==1?(Fe=Vr,ke=qt):(Fe=Wr,ke=Qt),qo(Ni(Fe,ke),Sn(ke-Fe)),Tn||$o(0,j)),!Tn&&!An&&($o(0,0),qo(0,0))}if(Un._x=Tn,Un._y=An,y==null){if(N){if(tp!=null){let[ge,Ee]=mn.scales;mn.values[0]=ge!=null?qi(R.ori==0?qt:Qt,ge):null,mn.values[1]=Ee!=null?qi(R.ori==1?qt:Qt,Ee):null}Zo(Cu,i,qt,Qt,k,be,O)}if(st){let ge=N&&mn.setSeries,Ee=ze.prox;hr==null?us<=Ee&&$i(Ds,$r,!0,ge):us>Ee?$i(null,$r,!0,ge):Ds!=hr&&$i(Ds,$r,!0,ge)}}_e&&(re.idx=O,nu()),E!==!1&&Rn("setCursor")}let Us=null;Object.defineProperty(i,"rect",{get(){return Us==null&&Yo(!1),Us}});function Yo(y=!1){y?Us=null:(Us=g.getBoundingClientRect(),Rn("syncRect",Us))}function Xf(y,E,N,O,V,j,he){le._lock||Ls&&y!=null&&y.movementX==0&&y.movementY==0||(iu(y,E,N,O,V,j,he,!1,y!=null),y!=null?ur(null,!0,!0):ur(E,!0,!1))}function iu(y,E,N,O,V,j,he,ge,Ee){if(Us==null&&Yo(!1),it(y),y!=null)N=y.clientX-Us.left,O=y.clientY-Us.top;else{if(N<0||O<0){qt=-10,Qt=-10;return}let[Oe,Fe]=mn.scales,ke=E.cursor.sync,[lt,Lt]=ke.values,[Ct,St]=ke.scales,[nt,Ye]=mn.match,Zt=E.axes[0].side%2==1,an=R.ori==0?k:be,Cn=R.ori==1?k:be,Ht=Zt?j:V,ln=Zt?V:j,ri=Zt?O:N,$n=Zt?N:O;if(Ct!=null?N=nt(Oe,Ct)?a(lt,b[Oe],an,0):-10:N=an*(ri/Ht),St!=null?O=Ye(Fe,St)?a(Lt,b[Fe],Cn,0):-10:O=Cn*($n/ln),R.ori==1){let vi=N;N=O,O=vi}}Ee&&(E==null||E.cursor.event.type==Cu)&&((N<=1||N>=k-1)&&(N=yr(N,k)),(O<=1||O>=be-1)&&(O=yr(O,be))),ge?(kf=N,zf=O,[Vr,Wr]=le.move(i,N,O)):(qt=N,Qt=O)}let su={width:0,height:0,left:0,top:0};function ru(){ol(su,!1)}let $f,qf,Yf,Zf;function Kf(y,E,N,O,V,j,he){Ls=!0,Tn=An=Un._x=Un._y=!1,iu(y,E,N,O,V,j,he,!0,!1),y!=null&&(dt(Iu,Uu,Jf,!1),Zo(nm,i,Vr,Wr,k,be,null));let{left:ge,top:Ee,width:Oe,height:Fe}=Yt;$f=ge,qf=Ee,Yf=Oe,Zf=Fe}function Jf(y,E,N,O,V,j,he){Ls=Un._x=Un._y=!1,iu(y,E,N,O,V,j,he,!1,!0);let{left:ge,top:Ee,width:Oe,height:Fe}=Yt,ke=Oe>0||Fe>0,lt=$f!=ge||qf!=Ee||Yf!=Oe||Zf!=Fe;if(ke&&lt&&ol(Yt),Un.setScale&&ke&&lt){let Lt=ge,Ct=Oe,St=Ee,nt=Fe;if(R.ori==1&&(Lt=Ee,Ct=Fe,St=ge,nt=Oe),Tn&&Ns(w,qi(Lt,w),qi(Lt+Ct,w)),An)for(let Ye in b){let Zt=b[Ye];Ye!=w&&Zt.from==null&&Zt.min!=Wt&&Ns(Ye,qi(St+nt,Ye),qi(St,Ye))}ru()}else le.lock&&(le._lock=!le._lock,ur(E,!0,y!=null));y!=null&&(Pt(Iu,Uu),Zo(Iu,i,qt,Qt,k,be,null))}function X_(y,E,N,O,V,j,he){if(le._lock)return;it(y);let ge=Ls;if(Ls){let Ee=!0,Oe=!0,Fe=10,ke,lt;R.ori==0?(ke=Tn,lt=An):(ke=An,lt=Tn),ke&&lt&&(Ee=qt<=Fe||qt>=k-Fe,Oe=Qt<=Fe||Qt>=be-Fe),ke&&Ee&&(qt=qt<Vr?0:k),lt&&Oe&&(Qt=Qt<Wr?0:be),ur(null,!0,!0),Ls=!1}qt=-10,Qt=-10,$.fill(null),ur(null,!0,!0),ge&&(Ls=ge)}function jf(y,E,N,O,V,j,he){le._lock||(it(y),Xo(),ru(),y!=null&&Zo(rm,i,qt,Qt,k,be,null))}function Qf(){A.forEach(Ev),G(i.width,i.height,!0)}br(Ol,to,Qf);let qr={};qr.mousedown=Kf,qr.mousemove=Xf,qr.mouseup=Jf,qr.dblclick=jf,qr.setSeries=(y,E,N,O)=>{let V=mn.match[2];N=V(i,E,N),N!=-1&&$i(N,O,!0,!1)},me&&(dt(nm,g,Kf),dt(Cu,g,Xf),dt(im,g,y=>{it(y),Yo(!1)}),dt(sm,g,X_),dt(rm,g,jf),Vu.add(i),i.syncRect=Yo);let al=i.hooks=n.hooks||{};function Rn(y,E,N){Xn?zt.push([y,E,N]):y in al&&al[y].forEach(O=>{O.call(null,i,E,N)})}(n.plugins||[]).forEach(y=>{for(let E in y.hooks)al[E]=(al[E]||[]).concat(y.hooks[E])});let ep=(y,E,N)=>N,mn=yn({key:null,setSeries:!1,filters:{pub:gm,sub:gm},scales:[w,x[1]?x[1].scale:null],match:[_m,_m,ep],values:[null,null]},le.sync);mn.match.length==2&&mn.match.push(ep),le.sync=mn;let tp=mn.key,ou=fg(tp);function Zo(y,E,N,O,V,j,he){mn.filters.pub(y,E,N,O,V,j,he)&&ou.pub(y,E,N,O,V,j,he)}ou.sub(i);function $_(y,E,N,O,V,j,he){mn.filters.sub(y,E,N,O,V,j,he)&&qr[y](null,E,N,O,V,j,he)}i.pub=$_;function q_(){ou.unsub(i),Vu.delete(i),cn.clear(),Bu(Ol,to,Qf),c.remove(),ve?.remove(),Rn("destroy")}i.destroy=q_;function au(){Rn("init",n,e),Wo(e||n.data,!1),B[w]?Qh(w,B[w]):Xo(),oe=Yt.show&&(Yt.width>0||Yt.height>0),ie=_e=!0,G(n.width,n.height)}return x.forEach(Fr),A.forEach(as),t?t instanceof HTMLElement?(t.appendChild(c),au()):t(i,au):au(),i}Pn.assign=yn;Pn.fmtNum=Ku;Pn.rangeNum=Fl;Pn.rangeLog=zl;Pn.rangeAsinh=Yu;Pn.orient=Mr;Pn.pxRatio=Dt;Pn.join=gx;Pn.fmtDate=ju,Pn.tzDate=Ax;Pn.sync=fg;{Pn.addGap=cv,Pn.clipGaps=Vl;let n=Pn.paths={points:xg};n.linear=bg,n.stepped=dv,n.bars=fv,n.spline=mv}var wr=class{constructor(e,t){this.keep=t;this.ys=Array.from({length:e},()=>[])}keep;t=[];ys;push(e,...t){if(this.t.push(e),t.forEach((i,s)=>this.ys[s].push(i!=null&&Number.isFinite(i)?i:null)),this.t.length>this.keep){this.t.shift();for(let i of this.ys)i.shift()}}},co=class{constructor(e,t,i,s=120,r=28){this.s=t;let o=document.createElement("span");o.className="spark",e.appendChild(o),this.plot=new Pn({width:s,height:r,cursor:{show:!1},legend:{show:!1},select:{show:!1},axes:[{show:!1},{show:!1}],scales:{x:{time:!1},y:{range:(a,l,c)=>[Math.min(0,l),c>0?c*1.1:1]}},series:[{},{stroke:i,width:1.5,fill:i+"33",points:{show:!1}}]},[[],[]],o),o.appendChild(this.label)}s;plot;label=document.createElement("span");update(e){this.plot.setData([this.s.t,this.s.ys[0]]),this.label.textContent=e}destroy(){this.plot.destroy()}},ql=class{constructor(e,t,i,s,r){this.s=t;this.plot=new Pn({width:s,height:r,scales:{x:{time:!0}},axes:[{stroke:"#8a96a3",grid:{stroke:"#1f2a35"}},{stroke:"#8a96a3",grid:{stroke:"#1f2a35"},scale:i[0].scale},...i.some(o=>o.scale==="r")?[{side:1,scale:"r",stroke:"#8a96a3",grid:{show:!1}}]:[]],series:[{},...i.map(o=>({label:o.label,stroke:o.colour,width:1.5,scale:o.scale,points:{show:!1}}))]},[[],...i.map(()=>[])],e)}s;plot;update(){this.plot.setData([this.s.t,...this.s.ys])}destroy(){this.plot.destroy()}};function*Eg(n){let e=-1,t=0;for(;t+2<n.length;)if(n[t]===0&&n[t+1]===0&&n[t+2]===1){if(e>=0){let i=t;i>e&&n[i-1]===0&&i--,yield n.subarray(e,i)}t+=3,e=t}else t++;e>=0&&e<n.length&&(yield n.subarray(e))}function Tg(n){for(let e of Eg(n))if(e.length>0&&(e[0]&31)===5)return!0;return!1}function Ag(n){for(let e of Eg(n))if(e.length>=4&&(e[0]&31)===7){let t=i=>i.toString(16).toUpperCase().padStart(2,"0");return`avc1.${t(e[1])}${t(e[2])}${t(e[3])}`}return null}var Rg="foxglove_msgs/msg/CompressedVideo",Tv="sensor_msgs/msg/CompressedImage",Av=8,Yl=class{frames=[];bytes=[];frame(){this.frames.push(performance.now())}received(e){this.bytes.push([performance.now(),e])}read(){let e=performance.now()-2e3;return this.frames=this.frames.filter(t=>t>=e),this.bytes=this.bytes.filter(([t])=>t>=e),{fps:this.frames.length/2,bps:this.bytes.reduce((t,[,i])=>t+i,0)/2}}};function Cg(n,e,t,i,s){let r=t.filter(p=>p.type===Rg),o=t.filter(p=>p.type===Tv);if(!r.length&&!o.length)return n.body.appendChild(te("p","muted","This robot publishes no camera topic (CompressedVideo or CompressedImage).")),[];let a=typeof VideoDecoder<"u",l=te("select");for(let p of r)l.appendChild(new Option(`${p.name} · H.264`,p.name));for(let p of o)l.appendChild(new Option(`${p.name} · picture by picture`,p.name));l.value=(r[0]??o[0]).name,n.box.querySelector("h2").appendChild(l);let c=te("p","muted"),h=te("div");n.body.append(h,c),vt.video={topic:"",codec:"",width:0,height:0,decoded:0,errors:0,fallback:""};let d=null,u="",m=(p,x="")=>{d?.(),h.replaceChildren(),c.textContent=u=x,l.value=p;let A=t.find(b=>b.name===p);d=A.type===Rg?v(A):f(A)},g=p=>{vt.video.fallback=p,o[0]?m(o[0].name,`${p}: showing ${o[0].name} instead.`):(d?.(),d=null,c.textContent=`${p}; this robot has no JPEG camera topic to show instead.`)};function v(p){let x=te("canvas","camera video");h.appendChild(x);let A=x.getContext("2d"),b=new Yl,C=null,w="",_=null,M=!0,U=!1;if(!a)return queueMicrotask(()=>g("this browser has no WebCodecs video decoder")),()=>{};let L=vt.video;Object.assign(L,{topic:p.name,codec:"",width:0,height:0,decoded:0,errors:0,fallback:""});let R=async(B,X)=>{w=Ag(X)??"avc1.42E01E",L.codec=w,_=[B];let D={codec:w,optimizeForLatency:!0},ne=!1;try{ne=!!(await VideoDecoder.isConfigSupported(D)).supported}catch{ne=!1}if(U)return;if(!ne){g(`this browser cannot decode ${w} video`);return}let q=new VideoDecoder({output:W=>{(x.width!==W.displayWidth||x.height!==W.displayHeight)&&(x.width=W.displayWidth,x.height=W.displayHeight),A.drawImage(W,0,0),L.width=W.displayWidth,L.height=W.displayHeight,W.close(),L.decoded++,b.frame(),On("camera"),On("video")},error:W=>{L.errors++,C=null,M=!0,L.decoded===0?g(`the video did not decode (${W.message})`):c.textContent=`decoder error (${W.message}); resuming at the next keyframe`}});q.configure(D),C=q;for(let W of _??[])q.decode(W);_=null},z=0,F=e.subscribe(p.name,B=>{s(p.name,{header:{stamp:B.timestamp}});let X=Rl(B.data);if(b.received(X.length),B.format!=="h264"){c.textContent=`${p.name} carries ${B.format} video, not h264`;return}let D=Tg(X);if(C&&C.decodeQueueSize>Av&&(M=!0),M&&!D)return;M=!1;let ne=new EncodedVideoChunk({type:D?"key":"delta",timestamp:z++*1e3,data:X});_?_.push(ne):C?C.decode(ne):D&&R(ne,X)},{type:p.type,queue_length:30}),P=window.setInterval(()=>{let B=b.read();n.info.textContent=`${p.name} · ${w||"waiting for a keyframe"}${L.width?` · ${L.width}×${L.height}`:""} · ${Nt(B.fps)} fps · ${zn(B.bps)}`},1e3);return()=>{U=!0,F(),clearInterval(P),C&&C.state!=="closed"&&C.close(),C=null}}function f(p){let x=te("img","camera"),A=te("canvas","camera bytes");A.style.display="none",h.append(x,A);let b=new Yl,C="",w=!1,_="",M=e.subscribe(p.name,async L=>{s(p.name,L),On("camera");let R=Rl(L.data);if(b.received(R.length),w)return;w=!0;let z=Vp(R);try{let F=new Blob([R],{type:`image/${z==="png"?"png":"jpeg"}`});(await createImageBitmap(F)).close(),C&&URL.revokeObjectURL(C),C=URL.createObjectURL(F),x.src=C,x.style.display="",A.style.display="none",b.frame(),c.textContent=u,_=`${L.format} · ${(R.length/1024).toFixed(0)} KiB`}catch{x.style.display="none",A.style.display="";let F=Math.max(1,Math.floor(Math.sqrt(R.length)));A.width=F,A.height=F;let P=A.getContext("2d"),B=P.createImageData(F,F);for(let X=0;X<F*F;X++){let D=R[X];B.data[X*4]=B.data[X*4+1]=B.data[X*4+2]=D,B.data[X*4+3]=255}P.putImageData(B,0,0),c.textContent=`not a decodable ${L.format} image (${z==="unknown"?"no image header":`${z} header, undecodable body`}): showing its ${R.length.toLocaleString()} bytes as grey levels`,_=`${L.format} · ${(R.length/1024).toFixed(0)} KiB`}finally{w=!1}},{type:p.type,queue_length:1}),U=window.setInterval(()=>{let L=b.read();n.info.textContent=`${p.name}${_?` · ${_}`:""} · ${Nt(L.fps)} fps · ${zn(L.bps)}`},1e3);return()=>{M(),clearInterval(U),C&&URL.revokeObjectURL(C)}}return l.addEventListener("change",()=>m(l.value)),m(l.value),i.push(()=>d?.()),[...r,...o].map(p=>p.name)}var rr={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},or={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},s0=0,Ld=1,r0=2;var Wa=1,o0=2,Uo=3,ar=0,jn=1,is=2,Pr=0,Oo=1,Nd=2,Dd=3,Ud=4,a0=5;var Lr=100,l0=101,c0=102,h0=103,u0=104,d0=200,f0=201,p0=202,m0=203,Od=204,Fd=205,g0=206,_0=207,y0=208,x0=209,v0=210,b0=211,S0=212,M0=213,w0=214,bc=0,Sc=1,Mc=2,Eo=3,wc=4,Ec=5,Tc=6,Ac=7,Bd=0,E0=1,T0=2,ss=0,kd=1,zd=2,Gd=3,Hd=4,Vd=5,Wd=6,Xd=7;var $d=300,Nr=301,Fo=302,nh=303,ih=304,Rc=1e3,es=1001,Cc=1002,Dn=1003,A0=1004;var Xa=1005;var Jn=1006,sh=1007;var Ts=1008;var xi=1009,qd=1010,Yd=1011,Bo=1012,rh=1013,Bi=1014,ki=1015,zi=1016,oh=1017,ah=1018,Dr=1020,Zd=35902,Kd=35899,Jd=1021,jd=1022,Gi=1023,Ms=1026,As=1027,Qd=1028,lh=1029,lr=1030,ch=1031;var hh=1033,$a=33776,qa=33777,Ya=33778,Za=33779,uh=35840,dh=35841,fh=35842,ph=35843,mh=36196,gh=37492,_h=37496,yh=37488,xh=37489,Ka=37490,vh=37491,bh=37808,Sh=37809,Mh=37810,wh=37811,Eh=37812,Th=37813,Ah=37814,Rh=37815,Ch=37816,Ih=37817,Ph=37818,Lh=37819,Nh=37820,Dh=37821,Uh=36492,Oh=36494,Fh=36495,Bh=36283,kh=36284,Ja=36285,zh=36286;var Ma=2300,Ic=2301,xc=2302,Ed=2303,Td=2400,Ad=2401,Rd=2402;var R0=3200;var ef=0,C0=1,Rs="",fi="srgb",wa="srgb-linear",Ea="linear",Ft="srgb";var vc=7680;var I0=519,P0=512,L0=513,N0=514,tf=515,D0=516,U0=517,nf=518,sf=519,O0=35044;var rf="300 es",Ti=2e3,Ta=2001;function Rv(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function Cv(n){return ArrayBuffer.isView(n)&&!(n instanceof DataView)}function Aa(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function F0(){let n=Aa("canvas");return n.style.display="block",n}var Ig={},To=null;function of(...n){let e="THREE."+n.shift();To?To("log",e,...n):console.log(e,...n)}function B0(n){let e=n[0];if(typeof e=="string"&&e.startsWith("TSL:")){let t=n[1];t&&t.isStackTrace?n[0]+=" "+t.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function Ke(...n){n=B0(n);let e="THREE."+n.shift();if(To)To("warn",e,...n);else{let t=n[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...n)}}function ot(...n){n=B0(n);let e="THREE."+n.shift();if(To)To("error",e,...n);else{let t=n[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...n)}}function va(...n){let e=n.join(" ");e in Ig||(Ig[e]=!0,Ke(...n))}function k0(n,e,t){return new Promise(function(i,s){function r(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:s();break;case n.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:i()}}setTimeout(r,t)})}var z0={[bc]:bc,[Mc]:Tc,[wc]:wc,[Eo]:Ec,[Sc]:Sc,[Tc]:Mc,[Ac]:Ac,[Ec]:Eo},Fi=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let i=this._listeners;i[e]===void 0&&(i[e]=[]),i[e].indexOf(t)===-1&&i[e].push(t)}hasEventListener(e,t){let i=this._listeners;return i===void 0?!1:i[e]!==void 0&&i[e].indexOf(t)!==-1}removeEventListener(e,t){let i=this._listeners;if(i===void 0)return;let s=i[e];if(s!==void 0){let r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){let t=this._listeners;if(t===void 0)return;let i=t[e.type];if(i!==void 0){e.target=this;let s=i.slice(0);for(let r=0,o=s.length;r<o;r++)s[r].call(this,e);e.target=null}}},Gn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Pg=1234567,ba=Math.PI/180,Ao=180/Math.PI;function ko(){let n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(Gn[n&255]+Gn[n>>8&255]+Gn[n>>16&255]+Gn[n>>24&255]+"-"+Gn[e&255]+Gn[e>>8&255]+"-"+Gn[e>>16&15|64]+Gn[e>>24&255]+"-"+Gn[t&63|128]+Gn[t>>8&255]+"-"+Gn[t>>16&255]+Gn[t>>24&255]+Gn[i&255]+Gn[i>>8&255]+Gn[i>>16&255]+Gn[i>>24&255]).toLowerCase()}function bt(n,e,t){return Math.max(e,Math.min(t,n))}function af(n,e){return(n%e+e)%e}function Iv(n,e,t,i,s){return i+(n-e)*(s-i)/(t-e)}function Pv(n,e,t){return n!==e?(t-n)/(e-n):0}function Sa(n,e,t){return(1-t)*n+t*e}function Lv(n,e,t,i){return Sa(n,e,1-Math.exp(-t*i))}function Nv(n,e=1){return e-Math.abs(af(n,e*2)-e)}function Dv(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*(3-2*n))}function Uv(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*n*(n*(n*6-15)+10))}function Ov(n,e){return n+Math.floor(Math.random()*(e-n+1))}function Fv(n,e){return n+Math.random()*(e-n)}function Bv(n){return n*(.5-Math.random())}function kv(n){n!==void 0&&(Pg=n);let e=Pg+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function zv(n){return n*ba}function Gv(n){return n*Ao}function Hv(n){return n>0&&Number.isInteger(n)&&2**Math.round(Math.log2(n))===n}function Vv(n){return Math.pow(2,Math.ceil(Math.log(n)/Math.LN2))}function lf(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function Wv(n,e,t,i,s){let r=Math.cos,o=Math.sin,a=r(t/2),l=o(t/2),c=r((e+i)/2),h=o((e+i)/2),d=r((e-i)/2),u=o((e-i)/2),m=r((i-e)/2),g=o((i-e)/2);switch(s){case"XYX":n.set(a*h,l*d,l*u,a*c);break;case"YZY":n.set(l*u,a*h,l*d,a*c);break;case"ZXZ":n.set(l*d,l*u,a*h,a*c);break;case"XZX":n.set(a*h,l*g,l*m,a*c);break;case"YXY":n.set(l*m,a*h,l*g,a*c);break;case"ZYZ":n.set(l*g,l*m,a*h,a*c);break;default:Ke("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+s)}}function cf(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function G0(n,e){if(e.constructor===Float32Array)return n;let t=cf(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/t,-1)}function H0(n,e){if(e.constructor===Float32Array)return n;let t=cf(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*t)}var hf={DEG2RAD:ba,RAD2DEG:Ao,generateUUID:ko,clamp:bt,euclideanModulo:af,mapLinear:Iv,inverseLerp:Pv,lerp:Sa,damp:Lv,pingpong:Nv,smoothstep:Dv,smootherstep:Uv,randInt:Ov,randFloat:Fv,randFloatSpread:Bv,seededRandom:kv,degToRad:zv,radToDeg:Gv,isPowerOfTwo:Hv,ceilPowerOfTwo:Vv,floorPowerOfTwo:lf,setQuaternionFromProperEuler:Wv,normalize:H0,denormalize:G0},mf=class mf{constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,i=this.y,s=e.elements;return this.x=s[0]*t+s[3]*i+s[6],this.y=s[1]*t+s[4]*i+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=bt(this.x,e.x,t.x),this.y=bt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=bt(this.x,e,t),this.y=bt(this.y,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(bt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(bt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y;return t*t+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let i=Math.cos(t),s=Math.sin(t),r=this.x-e.x,o=this.y-e.y;return this.x=r*i-o*s+e.x,this.y=r*s+o*i+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};mf.prototype.isVector2=!0;var ut=mf,gi=class{constructor(e=0,t=0,i=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=i,this._w=s}static slerpFlat(e,t,i,s,r,o,a){let l=i[s+0],c=i[s+1],h=i[s+2],d=i[s+3],u=r[o+0],m=r[o+1],g=r[o+2],v=r[o+3];if(d!==v||l!==u||c!==m||h!==g){let f=l*u+c*m+h*g+d*v;f<0&&(u=-u,m=-m,g=-g,v=-v,f=-f);let p=1-a;if(f<.9995){let x=Math.acos(f),A=Math.sin(x);p=Math.sin(p*x)/A,a=Math.sin(a*x)/A,l=l*p+u*a,c=c*p+m*a,h=h*p+g*a,d=d*p+v*a}else{l=l*p+u*a,c=c*p+m*a,h=h*p+g*a,d=d*p+v*a;let x=1/Math.sqrt(l*l+c*c+h*h+d*d);l*=x,c*=x,h*=x,d*=x}}e[t]=l,e[t+1]=c,e[t+2]=h,e[t+3]=d}static multiplyQuaternionsFlat(e,t,i,s,r,o){let a=i[s],l=i[s+1],c=i[s+2],h=i[s+3],d=r[o],u=r[o+1],m=r[o+2],g=r[o+3];return e[t]=a*g+h*d+l*m-c*u,e[t+1]=l*g+h*u+c*d-a*m,e[t+2]=c*g+h*m+a*u-l*d,e[t+3]=h*g-a*d-l*u-c*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,i,s){return this._x=e,this._y=t,this._z=i,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let i=e._x,s=e._y,r=e._z,o=e._order,a=Math.cos,l=Math.sin,c=a(i/2),h=a(s/2),d=a(r/2),u=l(i/2),m=l(s/2),g=l(r/2);switch(o){case"XYZ":this._x=u*h*d+c*m*g,this._y=c*m*d-u*h*g,this._z=c*h*g+u*m*d,this._w=c*h*d-u*m*g;break;case"YXZ":this._x=u*h*d+c*m*g,this._y=c*m*d-u*h*g,this._z=c*h*g-u*m*d,this._w=c*h*d+u*m*g;break;case"ZXY":this._x=u*h*d-c*m*g,this._y=c*m*d+u*h*g,this._z=c*h*g+u*m*d,this._w=c*h*d-u*m*g;break;case"ZYX":this._x=u*h*d-c*m*g,this._y=c*m*d+u*h*g,this._z=c*h*g-u*m*d,this._w=c*h*d+u*m*g;break;case"YZX":this._x=u*h*d+c*m*g,this._y=c*m*d+u*h*g,this._z=c*h*g-u*m*d,this._w=c*h*d-u*m*g;break;case"XZY":this._x=u*h*d-c*m*g,this._y=c*m*d-u*h*g,this._z=c*h*g+u*m*d,this._w=c*h*d+u*m*g;break;default:Ke("Quaternion: .setFromEuler() encountered an unknown order: "+o)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let i=t/2,s=Math.sin(i);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,i=t[0],s=t[4],r=t[8],o=t[1],a=t[5],l=t[9],c=t[2],h=t[6],d=t[10],u=i+a+d;if(u>0){let m=.5/Math.sqrt(u+1);this._w=.25/m,this._x=(h-l)*m,this._y=(r-c)*m,this._z=(o-s)*m}else if(i>a&&i>d){let m=2*Math.sqrt(1+i-a-d);this._w=(h-l)/m,this._x=.25*m,this._y=(s+o)/m,this._z=(r+c)/m}else if(a>d){let m=2*Math.sqrt(1+a-i-d);this._w=(r-c)/m,this._x=(s+o)/m,this._y=.25*m,this._z=(l+h)/m}else{let m=2*Math.sqrt(1+d-i-a);this._w=(o-s)/m,this._x=(r+c)/m,this._y=(l+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let i=e.dot(t)+1;return i<1e-8?(i=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=i):(this._x=0,this._y=-e.z,this._z=e.y,this._w=i)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=i),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(bt(this.dot(e),-1,1)))}rotateTowards(e,t){let i=this.angleTo(e);if(i===0)return this;let s=Math.min(1,t/i);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=t._x,l=t._y,c=t._z,h=t._w;return this._x=i*h+o*a+s*c-r*l,this._y=s*h+o*l+r*a-i*c,this._z=r*h+o*c+i*l-s*a,this._w=o*h-i*a-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=this.dot(e);a<0&&(i=-i,s=-s,r=-r,o=-o,a=-a);let l=1-t;if(a<.9995){let c=Math.acos(a),h=Math.sin(c);l=Math.sin(l*c)/h,t=Math.sin(t*c)/h,this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+o*t,this._onChangeCallback()}else this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+o*t,this.normalize();return this}slerpQuaternions(e,t,i){return this.copy(e).slerp(t,i)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),i=Math.random(),s=Math.sqrt(1-i),r=Math.sqrt(i);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},gf=class gf{constructor(e=0,t=0,i=0){this.x=e,this.y=t,this.z=i}set(e,t,i){return i===void 0&&(i=this.z),this.x=e,this.y=t,this.z=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Lg.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Lg.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*i+r[6]*s,this.y=r[1]*t+r[4]*i+r[7]*s,this.z=r[2]*t+r[5]*i+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=e.elements,o=1/(r[3]*t+r[7]*i+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*i+r[8]*s+r[12])*o,this.y=(r[1]*t+r[5]*i+r[9]*s+r[13])*o,this.z=(r[2]*t+r[6]*i+r[10]*s+r[14])*o,this}applyQuaternion(e){let t=this.x,i=this.y,s=this.z,r=e.x,o=e.y,a=e.z,l=e.w,c=2*(o*s-a*i),h=2*(a*t-r*s),d=2*(r*i-o*t);return this.x=t+l*c+o*d-a*h,this.y=i+l*h+a*c-r*d,this.z=s+l*d+r*h-o*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*i+r[8]*s,this.y=r[1]*t+r[5]*i+r[9]*s,this.z=r[2]*t+r[6]*i+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=bt(this.x,e.x,t.x),this.y=bt(this.y,e.y,t.y),this.z=bt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=bt(this.x,e,t),this.y=bt(this.y,e,t),this.z=bt(this.z,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(bt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let i=e.x,s=e.y,r=e.z,o=t.x,a=t.y,l=t.z;return this.x=s*l-r*a,this.y=r*o-i*l,this.z=i*a-s*o,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let i=e.dot(this)/t;return this.copy(e).multiplyScalar(i)}projectOnPlane(e){return rd.copy(this).projectOnVector(e),this.sub(rd)}reflect(e){return this.sub(rd.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(bt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y,s=this.z-e.z;return t*t+i*i+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,i){let s=Math.sin(t)*e;return this.x=s*Math.sin(i),this.y=Math.cos(t)*e,this.z=s*Math.cos(i),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,i){return this.x=e*Math.sin(t),this.y=i,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),i=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=i,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,i=Math.sqrt(1-t*t);return this.x=i*Math.cos(e),this.y=t,this.z=i*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};gf.prototype.isVector3=!0;var J=gf,rd=new J,Lg=new gi,_f=class _f{constructor(e,t,i,s,r,o,a,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,l,c)}set(e,t,i,s,r,o,a,l,c){let h=this.elements;return h[0]=e,h[1]=s,h[2]=a,h[3]=t,h[4]=r,h[5]=l,h[6]=i,h[7]=o,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],this}extractBasis(e,t,i){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[3],l=i[6],c=i[1],h=i[4],d=i[7],u=i[2],m=i[5],g=i[8],v=s[0],f=s[3],p=s[6],x=s[1],A=s[4],b=s[7],C=s[2],w=s[5],_=s[8];return r[0]=o*v+a*x+l*C,r[3]=o*f+a*A+l*w,r[6]=o*p+a*b+l*_,r[1]=c*v+h*x+d*C,r[4]=c*f+h*A+d*w,r[7]=c*p+h*b+d*_,r[2]=u*v+m*x+g*C,r[5]=u*f+m*A+g*w,r[8]=u*p+m*b+g*_,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8];return t*o*h-t*a*c-i*r*h+i*a*l+s*r*c-s*o*l}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8],d=h*o-a*c,u=a*l-h*r,m=c*r-o*l,g=t*d+i*u+s*m;if(g===0)return this.set(0,0,0,0,0,0,0,0,0);let v=1/g;return e[0]=d*v,e[1]=(s*c-h*i)*v,e[2]=(a*i-s*o)*v,e[3]=u*v,e[4]=(h*t-s*l)*v,e[5]=(s*r-a*t)*v,e[6]=m*v,e[7]=(i*l-c*t)*v,e[8]=(o*t-i*r)*v,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,i,s,r,o,a){let l=Math.cos(r),c=Math.sin(r);return this.set(i*l,i*c,-i*(l*o+c*a)+o+e,-s*c,s*l,-s*(-c*o+l*a)+a+t,0,0,1),this}scale(e,t){return va("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(od.makeScale(e,t)),this}rotate(e){return va("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(od.makeRotation(-e)),this}translate(e,t){return va("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(od.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,i,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<9;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<9;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e}clone(){return new this.constructor().fromArray(this.elements)}};_f.prototype.isMatrix3=!0;var at=_f,od=new at,Ng=new at().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Dg=new at().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function Xv(){let n={enabled:!0,workingColorSpace:wa,spaces:{},convert:function(s,r,o){return this.enabled===!1||r===o||!r||!o||(this.spaces[r].transfer===Ft&&(s.r=Ss(s.r),s.g=Ss(s.g),s.b=Ss(s.b)),this.spaces[r].primaries!==this.spaces[o].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[o].fromXYZ)),this.spaces[o].transfer===Ft&&(s.r=wo(s.r),s.g=wo(s.g),s.b=wo(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Rs?Ea:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,o){return s.copy(this.spaces[o].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[wa]:{primaries:e,whitePoint:i,transfer:Ea,toXYZ:Ng,fromXYZ:Dg,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:fi},outputColorSpaceConfig:{drawingBufferColorSpace:fi}},[fi]:{primaries:e,whitePoint:i,transfer:Ft,toXYZ:Ng,fromXYZ:Dg,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:fi}}}),n}var Tt=Xv();function Ss(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function wo(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}var ho,Pc=class{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let i;if(e instanceof HTMLCanvasElement)i=e;else{ho===void 0&&(ho=Aa("canvas")),ho.width=e.width,ho.height=e.height;let s=ho.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),i=ho}return i.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=Aa("canvas");t.width=e.width,t.height=e.height;let i=t.getContext("2d");i.drawImage(e,0,0,e.width,e.height);let s=i.getImageData(0,0,e.width,e.height),r=s.data;for(let o=0;o<r.length;o++)r[o]=Ss(r[o]/255)*255;return i.putImageData(s,0,0),t}else if(e.data){let t=e.data.slice(0);for(let i=0;i<t.length;i++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[i]=Math.floor(Ss(t[i]/255)*255):t[i]=Ss(t[i]);return{data:t,width:e.width,height:e.height}}else return Ke("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},$v=0,Ro=class{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:$v++}),this.uuid=ko(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){let t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let i={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let o=0,a=s.length;o<a;o++)s[o].isDataTexture?r.push(ad(s[o].image)):r.push(ad(s[o]))}else r=ad(s);i.url=r}return t||(e.images[this.uuid]=i),i}};function ad(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?Pc.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(Ke("Texture: Unable to serialize Texture."),{})}var qv=0,ld=new J,ei=class n extends Fi{constructor(e=n.DEFAULT_IMAGE,t=n.DEFAULT_MAPPING,i=es,s=es,r=Jn,o=Ts,a=Gi,l=xi,c=n.DEFAULT_ANISOTROPY,h=Rs){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:qv++}),this.uuid=ko(),this.name="",this.source=new Ro(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=i,this.wrapT=s,this.magFilter=r,this.minFilter=o,this.anisotropy=c,this.format=a,this.internalFormat=null,this.type=l,this.offset=new ut(0,0),this.repeat=new ut(1,1),this.center=new ut(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new at,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(ld).x}get height(){return this.source.getSize(ld).y}get depth(){return this.source.getSize(ld).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(let t in e){let i=e[t];if(i===void 0){Ke(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){Ke(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&i&&s.isVector2&&i.isVector2||s&&i&&s.isVector3&&i.isVector3||s&&i&&s.isMatrix3&&i.isMatrix3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),t||(e.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==$d)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case Rc:e.x=e.x-Math.floor(e.x);break;case es:e.x=e.x<0?0:1;break;case Cc:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case Rc:e.y=e.y-Math.floor(e.y);break;case es:e.y=e.y<0?0:1;break;case Cc:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};ei.DEFAULT_IMAGE=null;ei.DEFAULT_MAPPING=$d;ei.DEFAULT_ANISOTROPY=1;var yf=class yf{constructor(e=0,t=0,i=0,s=1){this.x=e,this.y=t,this.z=i,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,i,s){return this.x=e,this.y=t,this.z=i,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=this.w,o=e.elements;return this.x=o[0]*t+o[4]*i+o[8]*s+o[12]*r,this.y=o[1]*t+o[5]*i+o[9]*s+o[13]*r,this.z=o[2]*t+o[6]*i+o[10]*s+o[14]*r,this.w=o[3]*t+o[7]*i+o[11]*s+o[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,i,s,r,l=e.elements,c=l[0],h=l[4],d=l[8],u=l[1],m=l[5],g=l[9],v=l[2],f=l[6],p=l[10];if(Math.abs(h-u)<.01&&Math.abs(d-v)<.01&&Math.abs(g-f)<.01){if(Math.abs(h+u)<.1&&Math.abs(d+v)<.1&&Math.abs(g+f)<.1&&Math.abs(c+m+p-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let A=(c+1)/2,b=(m+1)/2,C=(p+1)/2,w=(h+u)/4,_=(d+v)/4,M=(g+f)/4;return A>b&&A>C?A<.01?(i=0,s=.707106781,r=.707106781):(i=Math.sqrt(A),s=w/i,r=_/i):b>C?b<.01?(i=.707106781,s=0,r=.707106781):(s=Math.sqrt(b),i=w/s,r=M/s):C<.01?(i=.707106781,s=.707106781,r=0):(r=Math.sqrt(C),i=_/r,s=M/r),this.set(i,s,r,t),this}let x=Math.sqrt((f-g)*(f-g)+(d-v)*(d-v)+(u-h)*(u-h));return Math.abs(x)<.001&&(x=1),this.x=(f-g)/x,this.y=(d-v)/x,this.z=(u-h)/x,this.w=Math.acos((c+m+p-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=bt(this.x,e.x,t.x),this.y=bt(this.y,e.y,t.y),this.z=bt(this.z,e.z,t.z),this.w=bt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=bt(this.x,e,t),this.y=bt(this.y,e,t),this.z=bt(this.z,e,t),this.w=bt(this.w,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(bt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this.w=e.w+(t.w-e.w)*i,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};yf.prototype.isVector4=!0;var sn=yf,Lc=class extends Fi{constructor(e=1,t=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Jn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=i.depth,this.scissor=new sn(0,0,e,t),this.scissorTest=!1,this.viewport=new sn(0,0,e,t),this.textures=[];let s=i.count;for(let r=0;r<s;r++)this.textures[r]=new ei({width:e,height:t,depth:i.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(e={}){let t={minFilter:Jn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,i=1){if(this.width!==e||this.height!==t||this.depth!==i){this.width=e,this.height=t,this.depth=i;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=i,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,i=e.textures.length;t<i;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;let s=Object.assign({},e.textures[t].image);this.textures[t].source=new Ro(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){let t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},_i=class extends Lc{constructor(e=1,t=1,i={}){super(e,t,i),this.isWebGLRenderTarget=!0}},Ra=class extends ei{constructor(e=null,t=1,i=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Dn,this.minFilter=Dn,this.wrapR=es,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var Nc=class extends ei{constructor(e=null,t=1,i=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Dn,this.minFilter=Dn,this.wrapR=es,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}};var th=class th{constructor(e,t,i,s,r,o,a,l,c,h,d,u,m,g,v,f){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,l,c,h,d,u,m,g,v,f)}set(e,t,i,s,r,o,a,l,c,h,d,u,m,g,v,f){let p=this.elements;return p[0]=e,p[4]=t,p[8]=i,p[12]=s,p[1]=r,p[5]=o,p[9]=a,p[13]=l,p[2]=c,p[6]=h,p[10]=d,p[14]=u,p[3]=m,p[7]=g,p[11]=v,p[15]=f,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new th().fromArray(this.elements)}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],t[9]=i[9],t[10]=i[10],t[11]=i[11],t[12]=i[12],t[13]=i[13],t[14]=i[14],t[15]=i[15],this}copyPosition(e){let t=this.elements,i=e.elements;return t[12]=i[12],t[13]=i[13],t[14]=i[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,i){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),i.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(e,t,i){return this.set(e.x,t.x,i.x,0,e.y,t.y,i.y,0,e.z,t.z,i.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();let t=this.elements,i=e.elements,s=1/uo.setFromMatrixColumn(e,0).length(),r=1/uo.setFromMatrixColumn(e,1).length(),o=1/uo.setFromMatrixColumn(e,2).length();return t[0]=i[0]*s,t[1]=i[1]*s,t[2]=i[2]*s,t[3]=0,t[4]=i[4]*r,t[5]=i[5]*r,t[6]=i[6]*r,t[7]=0,t[8]=i[8]*o,t[9]=i[9]*o,t[10]=i[10]*o,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,i=e.x,s=e.y,r=e.z,o=Math.cos(i),a=Math.sin(i),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),d=Math.sin(r);if(e.order==="XYZ"){let u=o*h,m=o*d,g=a*h,v=a*d;t[0]=l*h,t[4]=-l*d,t[8]=c,t[1]=m+g*c,t[5]=u-v*c,t[9]=-a*l,t[2]=v-u*c,t[6]=g+m*c,t[10]=o*l}else if(e.order==="YXZ"){let u=l*h,m=l*d,g=c*h,v=c*d;t[0]=u+v*a,t[4]=g*a-m,t[8]=o*c,t[1]=o*d,t[5]=o*h,t[9]=-a,t[2]=m*a-g,t[6]=v+u*a,t[10]=o*l}else if(e.order==="ZXY"){let u=l*h,m=l*d,g=c*h,v=c*d;t[0]=u-v*a,t[4]=-o*d,t[8]=g+m*a,t[1]=m+g*a,t[5]=o*h,t[9]=v-u*a,t[2]=-o*c,t[6]=a,t[10]=o*l}else if(e.order==="ZYX"){let u=o*h,m=o*d,g=a*h,v=a*d;t[0]=l*h,t[4]=g*c-m,t[8]=u*c+v,t[1]=l*d,t[5]=v*c+u,t[9]=m*c-g,t[2]=-c,t[6]=a*l,t[10]=o*l}else if(e.order==="YZX"){let u=o*l,m=o*c,g=a*l,v=a*c;t[0]=l*h,t[4]=v-u*d,t[8]=g*d+m,t[1]=d,t[5]=o*h,t[9]=-a*h,t[2]=-c*h,t[6]=m*d+g,t[10]=u-v*d}else if(e.order==="XZY"){let u=o*l,m=o*c,g=a*l,v=a*c;t[0]=l*h,t[4]=-d,t[8]=c*h,t[1]=u*d+v,t[5]=o*h,t[9]=m*d-g,t[2]=g*d-m,t[6]=a*h,t[10]=v*d+u}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(Yv,e,Zv)}lookAt(e,t,i){let s=this.elements;return ui.subVectors(e,t),ui.lengthSq()===0&&(ui.z=1),ui.normalize(),$s.crossVectors(i,ui),$s.lengthSq()===0&&(Math.abs(i.z)===1?ui.x+=1e-4:ui.z+=1e-4,ui.normalize(),$s.crossVectors(i,ui)),$s.normalize(),Zl.crossVectors(ui,$s),s[0]=$s.x,s[4]=Zl.x,s[8]=ui.x,s[1]=$s.y,s[5]=Zl.y,s[9]=ui.y,s[2]=$s.z,s[6]=Zl.z,s[10]=ui.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[4],l=i[8],c=i[12],h=i[1],d=i[5],u=i[9],m=i[13],g=i[2],v=i[6],f=i[10],p=i[14],x=i[3],A=i[7],b=i[11],C=i[15],w=s[0],_=s[4],M=s[8],U=s[12],L=s[1],R=s[5],z=s[9],F=s[13],P=s[2],B=s[6],X=s[10],D=s[14],ne=s[3],q=s[7],W=s[11],$=s[15];return r[0]=o*w+a*L+l*P+c*ne,r[4]=o*_+a*R+l*B+c*q,r[8]=o*M+a*z+l*X+c*W,r[12]=o*U+a*F+l*D+c*$,r[1]=h*w+d*L+u*P+m*ne,r[5]=h*_+d*R+u*B+m*q,r[9]=h*M+d*z+u*X+m*W,r[13]=h*U+d*F+u*D+m*$,r[2]=g*w+v*L+f*P+p*ne,r[6]=g*_+v*R+f*B+p*q,r[10]=g*M+v*z+f*X+p*W,r[14]=g*U+v*F+f*D+p*$,r[3]=x*w+A*L+b*P+C*ne,r[7]=x*_+A*R+b*B+C*q,r[11]=x*M+A*z+b*X+C*W,r[15]=x*U+A*F+b*D+C*$,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[12],o=e[1],a=e[5],l=e[9],c=e[13],h=e[2],d=e[6],u=e[10],m=e[14],g=e[3],v=e[7],f=e[11],p=e[15],x=l*m-c*u,A=a*m-c*d,b=a*u-l*d,C=o*m-c*h,w=o*u-l*h,_=o*d-a*h;return t*(v*x-f*A+p*b)-i*(g*x-f*C+p*w)+s*(g*A-v*C+p*_)-r*(g*b-v*w+f*_)}determinantAffine(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[1],o=e[5],a=e[9],l=e[2],c=e[6],h=e[10];return t*(o*h-a*c)-i*(r*h-a*l)+s*(r*c-o*l)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,i){let s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=i),this}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8],d=e[9],u=e[10],m=e[11],g=e[12],v=e[13],f=e[14],p=e[15],x=t*a-i*o,A=t*l-s*o,b=t*c-r*o,C=i*l-s*a,w=i*c-r*a,_=s*c-r*l,M=h*v-d*g,U=h*f-u*g,L=h*p-m*g,R=d*f-u*v,z=d*p-m*v,F=u*p-m*f,P=x*F-A*z+b*R+C*L-w*U+_*M;if(P===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let B=1/P;return e[0]=(a*F-l*z+c*R)*B,e[1]=(s*z-i*F-r*R)*B,e[2]=(v*_-f*w+p*C)*B,e[3]=(u*w-d*_-m*C)*B,e[4]=(l*L-o*F-c*U)*B,e[5]=(t*F-s*L+r*U)*B,e[6]=(f*b-g*_-p*A)*B,e[7]=(h*_-u*b+m*A)*B,e[8]=(o*z-a*L+c*M)*B,e[9]=(i*L-t*z-r*M)*B,e[10]=(g*w-v*b+p*x)*B,e[11]=(d*b-h*w-m*x)*B,e[12]=(a*U-o*R-l*M)*B,e[13]=(t*R-i*U+s*M)*B,e[14]=(v*A-g*C-f*x)*B,e[15]=(h*C-d*A+u*x)*B,this}scale(e){let t=this.elements,i=e.x,s=e.y,r=e.z;return t[0]*=i,t[4]*=s,t[8]*=r,t[1]*=i,t[5]*=s,t[9]*=r,t[2]*=i,t[6]*=s,t[10]*=r,t[3]*=i,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],i=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,i,s))}makeTranslation(e,t,i){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,i,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),i=Math.sin(e);return this.set(1,0,0,0,0,t,-i,0,0,i,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,0,i,0,0,1,0,0,-i,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,0,i,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let i=Math.cos(t),s=Math.sin(t),r=1-i,o=e.x,a=e.y,l=e.z,c=r*o,h=r*a;return this.set(c*o+i,c*a-s*l,c*l+s*a,0,c*a+s*l,h*a+i,h*l-s*o,0,c*l-s*a,h*l+s*o,r*l*l+i,0,0,0,0,1),this}makeScale(e,t,i){return this.set(e,0,0,0,0,t,0,0,0,0,i,0,0,0,0,1),this}makeShear(e,t,i,s,r,o){return this.set(1,i,r,0,e,1,o,0,t,s,1,0,0,0,0,1),this}compose(e,t,i){let s=this.elements,r=t._x,o=t._y,a=t._z,l=t._w,c=r+r,h=o+o,d=a+a,u=r*c,m=r*h,g=r*d,v=o*h,f=o*d,p=a*d,x=l*c,A=l*h,b=l*d,C=i.x,w=i.y,_=i.z;return s[0]=(1-(v+p))*C,s[1]=(m+b)*C,s[2]=(g-A)*C,s[3]=0,s[4]=(m-b)*w,s[5]=(1-(u+p))*w,s[6]=(f+x)*w,s[7]=0,s[8]=(g+A)*_,s[9]=(f-x)*_,s[10]=(1-(u+v))*_,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,i){let s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];let r=this.determinantAffine();if(r===0)return i.set(1,1,1),t.identity(),this;let o=uo.set(s[0],s[1],s[2]).length(),a=uo.set(s[4],s[5],s[6]).length(),l=uo.set(s[8],s[9],s[10]).length();r<0&&(o=-o),Di.copy(this);let c=1/o,h=1/a,d=1/l;return Di.elements[0]*=c,Di.elements[1]*=c,Di.elements[2]*=c,Di.elements[4]*=h,Di.elements[5]*=h,Di.elements[6]*=h,Di.elements[8]*=d,Di.elements[9]*=d,Di.elements[10]*=d,t.setFromRotationMatrix(Di),i.x=o,i.y=a,i.z=l,this}makePerspective(e,t,i,s,r,o,a=Ti,l=!1){let c=this.elements,h=2*r/(t-e),d=2*r/(i-s),u=(t+e)/(t-e),m=(i+s)/(i-s),g,v;if(l)g=r/(o-r),v=o*r/(o-r);else if(a===Ti)g=-(o+r)/(o-r),v=-2*o*r/(o-r);else if(a===Ta)g=-o/(o-r),v=-o*r/(o-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+a);return c[0]=h,c[4]=0,c[8]=u,c[12]=0,c[1]=0,c[5]=d,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=g,c[14]=v,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,i,s,r,o,a=Ti,l=!1){let c=this.elements,h=2/(t-e),d=2/(i-s),u=-(t+e)/(t-e),m=-(i+s)/(i-s),g,v;if(l)g=1/(o-r),v=o/(o-r);else if(a===Ti)g=-2/(o-r),v=-(o+r)/(o-r);else if(a===Ta)g=-1/(o-r),v=-r/(o-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+a);return c[0]=h,c[4]=0,c[8]=0,c[12]=u,c[1]=0,c[5]=d,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=g,c[14]=v,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<16;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<16;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e[t+9]=i[9],e[t+10]=i[10],e[t+11]=i[11],e[t+12]=i[12],e[t+13]=i[13],e[t+14]=i[14],e[t+15]=i[15],e}};th.prototype.isMatrix4=!0;var en=th,uo=new J,Di=new en,Yv=new J(0,0,0),Zv=new J(1,1,1),$s=new J,Zl=new J,ui=new J,Ug=new en,Og=new gi,js=class n{constructor(e=0,t=0,i=0,s=n.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=i,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,i,s=this._order){return this._x=e,this._y=t,this._z=i,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,i=!0){let s=e.elements,r=s[0],o=s[4],a=s[8],l=s[1],c=s[5],h=s[9],d=s[2],u=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(bt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-o,r)):(this._x=Math.atan2(u,c),this._z=0);break;case"YXZ":this._x=Math.asin(-bt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(a,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-d,r),this._z=0);break;case"ZXY":this._x=Math.asin(bt(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(-d,m),this._z=Math.atan2(-o,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-bt(d,-1,1)),Math.abs(d)<.9999999?(this._x=Math.atan2(u,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-o,c));break;case"YZX":this._z=Math.asin(bt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-d,r)):(this._x=0,this._y=Math.atan2(a,m));break;case"XZY":this._z=Math.asin(-bt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(u,c),this._y=Math.atan2(a,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:Ke("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,i===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,i){return Ug.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Ug,t,i)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return Og.setFromEuler(this),this.setFromQuaternion(Og,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};js.DEFAULT_ORDER="XYZ";var Ca=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},Kv=0,Fg=new J,fo=new gi,_s=new en,Kl=new J,ma=new J,Jv=new J,jv=new gi,Bg=new J(1,0,0),kg=new J(0,1,0),zg=new J(0,0,1),Gg={type:"added"},Qv={type:"removed"},po={type:"childadded",child:null},cd={type:"childremoved",child:null},ti=class n extends Fi{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Kv++}),this.uuid=ko(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=n.DEFAULT_UP.clone();let e=new J,t=new js,i=new gi,s=new J(1,1,1);function r(){i.setFromEuler(t,!1)}function o(){t.setFromQuaternion(i,void 0,!1)}t._onChange(r),i._onChange(o),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new en},normalMatrix:{value:new at}}),this.matrix=new en,this.matrixWorld=new en,this.matrixAutoUpdate=n.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=n.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Ca,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return fo.setFromAxisAngle(e,t),this.quaternion.multiply(fo),this}rotateOnWorldAxis(e,t){return fo.setFromAxisAngle(e,t),this.quaternion.premultiply(fo),this}rotateX(e){return this.rotateOnAxis(Bg,e)}rotateY(e){return this.rotateOnAxis(kg,e)}rotateZ(e){return this.rotateOnAxis(zg,e)}translateOnAxis(e,t){return Fg.copy(e).applyQuaternion(this.quaternion),this.position.add(Fg.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(Bg,e)}translateY(e){return this.translateOnAxis(kg,e)}translateZ(e){return this.translateOnAxis(zg,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(_s.copy(this.matrixWorld).invert())}lookAt(e,t,i){e.isVector3?Kl.copy(e):Kl.set(e,t,i);let s=this.parent;this.updateWorldMatrix(!0,!1),ma.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?_s.lookAt(ma,Kl,this.up):_s.lookAt(Kl,ma,this.up),this.quaternion.setFromRotationMatrix(_s),s&&(_s.extractRotation(s.matrixWorld),fo.setFromRotationMatrix(_s),this.quaternion.premultiply(fo.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(ot("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(Gg),po.child=e,this.dispatchEvent(po),po.child=null):ot("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(Qv),cd.child=e,this.dispatchEvent(cd),cd.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),_s.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),_s.multiply(e.parent.matrixWorld)),e.applyMatrix4(_s),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(Gg),po.child=e,this.dispatchEvent(po),po.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let i=0,s=this.children.length;i<s;i++){let o=this.children[i].getObjectByProperty(e,t);if(o!==void 0)return o}}getObjectsByProperty(e,t,i=[]){this[e]===t&&i.push(this);let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].getObjectsByProperty(e,t,i);return i}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ma,e,Jv),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ma,jv,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let e=this.pivot;if(e!==null){let t=e.x,i=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*i-r[8]*s,r[13]+=i-r[1]*t-r[5]*i-r[9]*s,r[14]+=s-r[2]*t-r[6]*i-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].updateMatrixWorld(e)}updateWorldMatrix(e,t,i=!1){let s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),t===!0){let r=this.children;for(let o=0,a=r.length;o<a;o++)r[o].updateWorldMatrix(!1,!0,i)}}toJSON(e){let t=e===void 0||typeof e=="string",i={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(a=>({...a,boundingBox:a.boundingBox?a.boundingBox.toJSON():void 0,boundingSphere:a.boundingSphere?a.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(a=>({...a})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(a,l){return a[l.uuid]===void 0&&(a[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);let a=this.geometry.parameters;if(a!==void 0&&a.shapes!==void 0){let l=a.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){let d=l[c];r(e.shapes,d)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let a=[];for(let l=0,c=this.material.length;l<c;l++)a.push(r(e.materials,this.material[l]));s.material=a}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let a=0;a<this.children.length;a++)s.children.push(this.children[a].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let a=0;a<this.animations.length;a++){let l=this.animations[a];s.animations.push(r(e.animations,l))}}if(t){let a=o(e.geometries),l=o(e.materials),c=o(e.textures),h=o(e.images),d=o(e.shapes),u=o(e.skeletons),m=o(e.animations),g=o(e.nodes);a.length>0&&(i.geometries=a),l.length>0&&(i.materials=l),c.length>0&&(i.textures=c),h.length>0&&(i.images=h),d.length>0&&(i.shapes=d),u.length>0&&(i.skeletons=u),m.length>0&&(i.animations=m),g.length>0&&(i.nodes=g)}return i.object=s,i;function o(a){let l=[];for(let c in a){let h=a[c];delete h.metadata,l.push(h)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let i=0;i<e.children.length;i++){let s=e.children[i];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};ti.DEFAULT_UP=new J(0,1,0);ti.DEFAULT_MATRIX_AUTO_UPDATE=!0;ti.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var Cr=class extends ti{constructor(){super(),this.isGroup=!0,this.type="Group"}},eb={type:"move"},Co=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Cr,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Cr,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new J,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new J),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Cr,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new J,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new J,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let i of e.hand.values())this._getHandJoint(t,i)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,i){let s=null,r=null,o=null,a=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){o=!0;for(let v of e.hand.values()){let f=t.getJointPose(v,i),p=this._getHandJoint(c,v);f!==null&&(p.matrix.fromArray(f.transform.matrix),p.matrix.decompose(p.position,p.quaternion,p.scale),p.matrixWorldNeedsUpdate=!0,p.jointRadius=f.radius),p.visible=f!==null}let h=c.joints["index-finger-tip"],d=c.joints["thumb-tip"],u=h.position.distanceTo(d.position),m=.02,g=.005;c.inputState.pinching&&u>m+g?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&u<=m-g&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,i),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));a!==null&&(s=t.getPose(e.targetRaySpace,i),s===null&&r!==null&&(s=r),s!==null&&(a.matrix.fromArray(s.transform.matrix),a.matrix.decompose(a.position,a.quaternion,a.scale),a.matrixWorldNeedsUpdate=!0,s.linearVelocity?(a.hasLinearVelocity=!0,a.linearVelocity.copy(s.linearVelocity)):a.hasLinearVelocity=!1,s.angularVelocity?(a.hasAngularVelocity=!0,a.angularVelocity.copy(s.angularVelocity)):a.hasAngularVelocity=!1,this.dispatchEvent(eb)))}return a!==null&&(a.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=o!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let i=new Cr;i.matrixAutoUpdate=!1,i.visible=!1,e.joints[t.jointName]=i,e.add(i)}return e.joints[t.jointName]}},V0={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},qs={h:0,s:0,l:0},Jl={h:0,s:0,l:0};function hd(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}var gt=class{constructor(e,t,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,i)}set(e,t,i){if(t===void 0&&i===void 0){let s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,i);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=fi){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,Tt.colorSpaceToWorking(this,t),this}setRGB(e,t,i,s=Tt.workingColorSpace){return this.r=e,this.g=t,this.b=i,Tt.colorSpaceToWorking(this,s),this}setHSL(e,t,i,s=Tt.workingColorSpace){if(e=af(e,1),t=bt(t,0,1),i=bt(i,0,1),t===0)this.r=this.g=this.b=i;else{let r=i<=.5?i*(1+t):i+t-i*t,o=2*i-r;this.r=hd(o,r,e+1/3),this.g=hd(o,r,e),this.b=hd(o,r,e-1/3)}return Tt.colorSpaceToWorking(this,s),this}setStyle(e,t=fi){function i(r){r!==void 0&&parseFloat(r)<1&&Ke("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r,o=s[1],a=s[2];switch(o){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:Ke("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){let r=s[1],o=r.length;if(o===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(o===6)return this.setHex(parseInt(r,16),t);Ke("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=fi){let i=V0[e.toLowerCase()];return i!==void 0?this.setHex(i,t):Ke("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=Ss(e.r),this.g=Ss(e.g),this.b=Ss(e.b),this}copyLinearToSRGB(e){return this.r=wo(e.r),this.g=wo(e.g),this.b=wo(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=fi){return Tt.workingToColorSpace(Hn.copy(this),e),Math.round(bt(Hn.r*255,0,255))*65536+Math.round(bt(Hn.g*255,0,255))*256+Math.round(bt(Hn.b*255,0,255))}getHexString(e=fi){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=Tt.workingColorSpace){Tt.workingToColorSpace(Hn.copy(this),t);let i=Hn.r,s=Hn.g,r=Hn.b,o=Math.max(i,s,r),a=Math.min(i,s,r),l,c,h=(a+o)/2;if(a===o)l=0,c=0;else{let d=o-a;switch(c=h<=.5?d/(o+a):d/(2-o-a),o){case i:l=(s-r)/d+(s<r?6:0);break;case s:l=(r-i)/d+2;break;case r:l=(i-s)/d+4;break}l/=6}return e.h=l,e.s=c,e.l=h,e}getRGB(e,t=Tt.workingColorSpace){return Tt.workingToColorSpace(Hn.copy(this),t),e.r=Hn.r,e.g=Hn.g,e.b=Hn.b,e}getStyle(e=fi){Tt.workingToColorSpace(Hn.copy(this),e);let t=Hn.r,i=Hn.g,s=Hn.b;return e!==fi?`color(${e} ${t.toFixed(3)} ${i.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(i*255)},${Math.round(s*255)})`}offsetHSL(e,t,i){return this.getHSL(qs),this.setHSL(qs.h+e,qs.s+t,qs.l+i)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,i){return this.r=e.r+(t.r-e.r)*i,this.g=e.g+(t.g-e.g)*i,this.b=e.b+(t.b-e.b)*i,this}lerpHSL(e,t){this.getHSL(qs),e.getHSL(Jl);let i=Sa(qs.h,Jl.h,t),s=Sa(qs.s,Jl.s,t),r=Sa(qs.l,Jl.l,t);return this.setHSL(i,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,i=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*i+r[6]*s,this.g=r[1]*t+r[4]*i+r[7]*s,this.b=r[2]*t+r[5]*i+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},Hn=new gt;gt.NAMES=V0;var Ia=class extends ti{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new js,this.environmentIntensity=1,this.environmentRotation=new js,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}},Ui=new J,ys=new J,ud=new J,xs=new J,mo=new J,go=new J,Hg=new J,dd=new J,fd=new J,pd=new J,md=new sn,gd=new sn,_d=new sn,Js=class n{constructor(e=new J,t=new J,i=new J){this.a=e,this.b=t,this.c=i}static getNormal(e,t,i,s){s.subVectors(i,t),Ui.subVectors(e,t),s.cross(Ui);let r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,i,s,r){Ui.subVectors(s,t),ys.subVectors(i,t),ud.subVectors(e,t);let o=Ui.dot(Ui),a=Ui.dot(ys),l=Ui.dot(ud),c=ys.dot(ys),h=ys.dot(ud),d=o*c-a*a;if(d===0)return r.set(0,0,0),null;let u=1/d,m=(c*l-a*h)*u,g=(o*h-a*l)*u;return r.set(1-m-g,g,m)}static containsPoint(e,t,i,s){return this.getBarycoord(e,t,i,s,xs)===null?!1:xs.x>=0&&xs.y>=0&&xs.x+xs.y<=1}static getInterpolation(e,t,i,s,r,o,a,l){return this.getBarycoord(e,t,i,s,xs)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,xs.x),l.addScaledVector(o,xs.y),l.addScaledVector(a,xs.z),l)}static getInterpolatedAttribute(e,t,i,s,r,o){return md.setScalar(0),gd.setScalar(0),_d.setScalar(0),md.fromBufferAttribute(e,t),gd.fromBufferAttribute(e,i),_d.fromBufferAttribute(e,s),o.setScalar(0),o.addScaledVector(md,r.x),o.addScaledVector(gd,r.y),o.addScaledVector(_d,r.z),o}static isFrontFacing(e,t,i,s){return Ui.subVectors(i,t),ys.subVectors(e,t),Ui.cross(ys).dot(s)<0}set(e,t,i){return this.a.copy(e),this.b.copy(t),this.c.copy(i),this}setFromPointsAndIndices(e,t,i,s){return this.a.copy(e[t]),this.b.copy(e[i]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,i,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,i),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Ui.subVectors(this.c,this.b),ys.subVectors(this.a,this.b),Ui.cross(ys).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return n.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return n.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,i,s,r){return n.getInterpolation(e,this.a,this.b,this.c,t,i,s,r)}containsPoint(e){return n.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return n.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let i=this.a,s=this.b,r=this.c,o,a;mo.subVectors(s,i),go.subVectors(r,i),dd.subVectors(e,i);let l=mo.dot(dd),c=go.dot(dd);if(l<=0&&c<=0)return t.copy(i);fd.subVectors(e,s);let h=mo.dot(fd),d=go.dot(fd);if(h>=0&&d<=h)return t.copy(s);let u=l*d-h*c;if(u<=0&&l>=0&&h<=0&&l-h>0)return o=l/(l-h),t.copy(i).addScaledVector(mo,o);pd.subVectors(e,r);let m=mo.dot(pd),g=go.dot(pd);if(g>=0&&m<=g)return t.copy(r);let v=m*c-l*g;if(v<=0&&c>=0&&g<=0)return a=c/(c-g),t.copy(i).addScaledVector(go,a);let f=h*g-m*d;if(f<=0&&d-h>=0&&m-g>=0)return Hg.subVectors(r,s),a=(d-h)/(d-h+(m-g)),t.copy(s).addScaledVector(Hg,a);let p=1/(f+v+u);return o=v*p,a=u*p,t.copy(i).addScaledVector(mo,o).addScaledVector(go,a)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},Qs=class{constructor(e=new J(1/0,1/0,1/0),t=new J(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t+=3)this.expandByPoint(Oi.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,i=e.count;t<i;t++)this.expandByPoint(Oi.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let i=Oi.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(i),this.max.copy(e).add(i),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let i=e.geometry;if(i!==void 0){let r=i.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let o=0,a=r.count;o<a;o++)e.isMesh===!0?e.getVertexPosition(o,Oi):Oi.fromBufferAttribute(r,o),Oi.applyMatrix4(e.matrixWorld),this.expandByPoint(Oi);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),jl.copy(e.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),jl.copy(i.boundingBox)),jl.applyMatrix4(e.matrixWorld),this.union(jl)}let s=e.children;for(let r=0,o=s.length;r<o;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Oi),Oi.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,i;return e.normal.x>0?(t=e.normal.x*this.min.x,i=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,i=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,i+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,i+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,i+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,i+=e.normal.z*this.min.z),t<=-e.constant&&i>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(ga),Ql.subVectors(this.max,ga),_o.subVectors(e.a,ga),yo.subVectors(e.b,ga),xo.subVectors(e.c,ga),Ys.subVectors(yo,_o),Zs.subVectors(xo,yo),Er.subVectors(_o,xo);let t=[0,-Ys.z,Ys.y,0,-Zs.z,Zs.y,0,-Er.z,Er.y,Ys.z,0,-Ys.x,Zs.z,0,-Zs.x,Er.z,0,-Er.x,-Ys.y,Ys.x,0,-Zs.y,Zs.x,0,-Er.y,Er.x,0];return!yd(t,_o,yo,xo,Ql)||(t=[1,0,0,0,1,0,0,0,1],!yd(t,_o,yo,xo,Ql))?!1:(ec.crossVectors(Ys,Zs),t=[ec.x,ec.y,ec.z],yd(t,_o,yo,xo,Ql))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Oi).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Oi).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(vs[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),vs[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),vs[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),vs[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),vs[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),vs[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),vs[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),vs[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(vs),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}},vs=[new J,new J,new J,new J,new J,new J,new J,new J],Oi=new J,jl=new Qs,_o=new J,yo=new J,xo=new J,Ys=new J,Zs=new J,Er=new J,ga=new J,Ql=new J,ec=new J,Tr=new J;function yd(n,e,t,i,s){for(let r=0,o=n.length-3;r<=o;r+=3){Tr.fromArray(n,r);let a=s.x*Math.abs(Tr.x)+s.y*Math.abs(Tr.y)+s.z*Math.abs(Tr.z),l=e.dot(Tr),c=t.dot(Tr),h=i.dot(Tr);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>a)return!1}return!0}var xn=new J,tc=new ut,tb=0,mi=class extends Fi{constructor(e,t,i=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:tb++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=i,this.usage=O0,this.updateRanges=[],this.gpuType=ki,this.version=0,this._normalizationScale=e!==void 0?cf(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,i){e*=this.itemSize,i*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[i+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,i=this.count;t<i;t++)tc.fromBufferAttribute(this,t),tc.applyMatrix3(e),this.setXY(t,tc.x,tc.y);else if(this.itemSize===3)for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyMatrix3(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}applyMatrix4(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyMatrix4(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyNormalMatrix(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.transformDirection(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let i=this.array[e*this.itemSize+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.array[e*this.itemSize+t]=i,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,i){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.array[e+0]=t,this.array[e+1]=i,this}setXYZ(e,t,i,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this}setXYZW(e,t,i,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):G0(e,this.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):H0(e,this.array)}};var Pa=class extends mi{constructor(e,t,i){super(new Uint16Array(e),t,i)}};var La=class extends mi{constructor(e,t,i){super(new Uint32Array(e),t,i)}};var Nn=class extends mi{constructor(e,t,i){super(new Float32Array(e),t,i)}},nb=new Qs,_a=new J,xd=new J,er=class{constructor(e=new J,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let i=this.center;t!==void 0?i.copy(t):nb.setFromPoints(e).getCenter(i);let s=0;for(let r=0,o=e.length;r<o;r++)s=Math.max(s,i.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let i=this.center.distanceToSquared(e);return t.copy(e),i>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;_a.subVectors(e,this.center);let t=_a.lengthSq();if(t>this.radius*this.radius){let i=Math.sqrt(t),s=(i-this.radius)*.5;this.center.addScaledVector(_a,s/i),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(xd.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(_a.copy(e.center).add(xd)),this.expandByPoint(_a.copy(e.center).sub(xd))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}},ib=0,Ei=new en,vd=new ti,vo=new J,di=new Qs,ya=new Qs,Ln=new J,ni=class n extends Fi{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:ib++}),this.uuid=ko(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(Rv(e)?La:Pa)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,i=0){this.groups.push({start:e,count:t,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let i=this.attributes.normal;if(i!==void 0){let r=new at().getNormalMatrix(e);i.applyNormalMatrix(r),i.needsUpdate=!0}let s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return Ei.makeRotationFromQuaternion(e),this.applyMatrix4(Ei),this}rotateX(e){return Ei.makeRotationX(e),this.applyMatrix4(Ei),this}rotateY(e){return Ei.makeRotationY(e),this.applyMatrix4(Ei),this}rotateZ(e){return Ei.makeRotationZ(e),this.applyMatrix4(Ei),this}translate(e,t,i){return Ei.makeTranslation(e,t,i),this.applyMatrix4(Ei),this}scale(e,t,i){return Ei.makeScale(e,t,i),this.applyMatrix4(Ei),this}lookAt(e){return vd.lookAt(e),vd.updateMatrix(),this.applyMatrix4(vd.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(vo).negate(),this.translate(vo.x,vo.y,vo.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let i=[];for(let s=0,r=e.length;s<r;s++){let o=e[s];i.push(o.x,o.y,o.z||0)}this.setAttribute("position",new Nn(i,3))}else{let i=Math.min(e.length,t.count);for(let s=0;s<i;s++){let r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&Ke("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Qs);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){ot("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new J(-1/0,-1/0,-1/0),new J(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let i=0,s=t.length;i<s;i++){let r=t[i];di.setFromBufferAttribute(r),this.morphTargetsRelative?(Ln.addVectors(this.boundingBox.min,di.min),this.boundingBox.expandByPoint(Ln),Ln.addVectors(this.boundingBox.max,di.max),this.boundingBox.expandByPoint(Ln)):(this.boundingBox.expandByPoint(di.min),this.boundingBox.expandByPoint(di.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&ot('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new er);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){ot("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new J,1/0);return}if(e){let i=this.boundingSphere.center;if(di.setFromBufferAttribute(e),t)for(let r=0,o=t.length;r<o;r++){let a=t[r];ya.setFromBufferAttribute(a),this.morphTargetsRelative?(Ln.addVectors(di.min,ya.min),di.expandByPoint(Ln),Ln.addVectors(di.max,ya.max),di.expandByPoint(Ln)):(di.expandByPoint(ya.min),di.expandByPoint(ya.max))}di.getCenter(i);let s=0;for(let r=0,o=e.count;r<o;r++)Ln.fromBufferAttribute(e,r),s=Math.max(s,i.distanceToSquared(Ln));if(t)for(let r=0,o=t.length;r<o;r++){let a=t[r],l=this.morphTargetsRelative;for(let c=0,h=a.count;c<h;c++)Ln.fromBufferAttribute(a,c),l&&(vo.fromBufferAttribute(e,c),Ln.add(vo)),s=Math.max(s,i.distanceToSquared(Ln))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&ot('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){ot("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let i=t.position,s=t.normal,r=t.uv,o=this.getAttribute("tangent");(o===void 0||o.count!==i.count)&&(o=new mi(new Float32Array(4*i.count),4),this.setAttribute("tangent",o));let a=[],l=[],c=new Uint8Array(i.count);for(let U=0;U<i.count;U++)a[U]=new J,l[U]=new J;let h=new J,d=new J,u=new J,m=new ut,g=new ut,v=new ut,f=new J,p=new J;function x(U,L,R){c[U]=c[L]=c[R]=1,h.fromBufferAttribute(i,U),d.fromBufferAttribute(i,L),u.fromBufferAttribute(i,R),m.fromBufferAttribute(r,U),g.fromBufferAttribute(r,L),v.fromBufferAttribute(r,R),d.sub(h),u.sub(h),g.sub(m),v.sub(m);let z=1/(g.x*v.y-v.x*g.y);isFinite(z)&&(f.copy(d).multiplyScalar(v.y).addScaledVector(u,-g.y).multiplyScalar(z),p.copy(u).multiplyScalar(g.x).addScaledVector(d,-v.x).multiplyScalar(z),a[U].add(f),a[L].add(f),a[R].add(f),l[U].add(p),l[L].add(p),l[R].add(p))}let A=this.groups;A.length===0&&(A=[{start:0,count:e.count}]);for(let U=0,L=A.length;U<L;++U){let R=A[U],z=R.start,F=R.count;for(let P=z,B=z+F;P<B;P+=3)x(e.getX(P+0),e.getX(P+1),e.getX(P+2))}let b=new J,C=new J,w=new J,_=new J;function M(U){w.fromBufferAttribute(s,U),_.copy(w);let L=a[U];b.copy(L),b.sub(w.multiplyScalar(w.dot(L))).normalize(),C.crossVectors(_,L);let z=C.dot(l[U])<0?-1:1;o.setXYZW(U,b.x,b.y,b.z,z)}for(let U=0,L=i.count;U<L;++U)c[U]&&M(U);this._transformed=!0}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==t.count)i=new mi(new Float32Array(t.count*3),3),this.setAttribute("normal",i);else for(let u=0,m=i.count;u<m;u++)i.setXYZ(u,0,0,0);let s=new J,r=new J,o=new J,a=new J,l=new J,c=new J,h=new J,d=new J;if(e)for(let u=0,m=e.count;u<m;u+=3){let g=e.getX(u+0),v=e.getX(u+1),f=e.getX(u+2);s.fromBufferAttribute(t,g),r.fromBufferAttribute(t,v),o.fromBufferAttribute(t,f),h.subVectors(o,r),d.subVectors(s,r),h.cross(d),a.fromBufferAttribute(i,g),l.fromBufferAttribute(i,v),c.fromBufferAttribute(i,f),a.add(h),l.add(h),c.add(h),i.setXYZ(g,a.x,a.y,a.z),i.setXYZ(v,l.x,l.y,l.z),i.setXYZ(f,c.x,c.y,c.z)}else for(let u=0,m=t.count;u<m;u+=3)s.fromBufferAttribute(t,u+0),r.fromBufferAttribute(t,u+1),o.fromBufferAttribute(t,u+2),h.subVectors(o,r),d.subVectors(s,r),h.cross(d),i.setXYZ(u+0,h.x,h.y,h.z),i.setXYZ(u+1,h.x,h.y,h.z),i.setXYZ(u+2,h.x,h.y,h.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,i=e.count;t<i;t++)Ln.fromBufferAttribute(e,t),Ln.normalize(),e.setXYZ(t,Ln.x,Ln.y,Ln.z)}toNonIndexed(){function e(a,l){let c=a.array,h=a.itemSize,d=a.normalized,u=new c.constructor(l.length*h),m=0,g=0;for(let v=0,f=l.length;v<f;v++){a.isInterleavedBufferAttribute?m=l[v]*a.data.stride+a.offset:m=l[v]*h;for(let p=0;p<h;p++)u[g++]=c[m++]}return new mi(u,h,d)}if(this.index===null)return Ke("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new n,i=this.index.array,s=this.attributes;for(let a in s){let l=s[a],c=e(l,i);t.setAttribute(a,c)}let r=this.morphAttributes;for(let a in r){let l=[],c=r[a];for(let h=0,d=c.length;h<d;h++){let u=c[h],m=e(u,i);l.push(m)}t.morphAttributes[a]=l}t.morphTargetsRelative=this.morphTargetsRelative;let o=this.groups;for(let a=0,l=o.length;a<l;a++){let c=o[a];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){let e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let l=this.parameters;for(let c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let i=this.attributes;for(let l in i){let c=i[l];e.data.attributes[l]=c.toJSON(e.data)}let s={},r=!1;for(let l in this.morphAttributes){let c=this.morphAttributes[l],h=[];for(let d=0,u=c.length;d<u;d++){let m=c[d];h.push(m.toJSON(e.data))}h.length>0&&(s[l]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);let o=this.groups;o.length>0&&(e.data.groups=JSON.parse(JSON.stringify(o)));let a=this.boundingSphere;return a!==null&&(e.data.boundingSphere=a.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let i=e.index;i!==null&&this.setIndex(i.clone());let s=e.attributes;for(let c in s){let h=s[c];this.setAttribute(c,h.clone(t))}let r=e.morphAttributes;for(let c in r){let h=[],d=r[c];for(let u=0,m=d.length;u<m;u++)h.push(d[u].clone(t));this.morphAttributes[c]=h}this.morphTargetsRelative=e.morphTargetsRelative;let o=e.groups;for(let c=0,h=o.length;c<h;c++){let d=o[c];this.addGroup(d.start,d.count,d.materialIndex)}let a=e.boundingBox;a!==null&&(this.boundingBox=a.clone());let l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}};var bd=new J,sb=new J,rb=new at,pi=class{constructor(e=new J(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,i,s){return this.normal.set(e,t,i),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,i){let s=bd.subVectors(i,t).cross(sb.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,i=!0){let s=e.delta(bd),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let o=-(e.start.dot(this.normal)+this.constant)/r;return i===!0&&(o<0||o>1)?null:t.copy(e.start).addScaledVector(s,o)}intersectsLine(e){let t=this.distanceToPoint(e.start),i=this.distanceToPoint(e.end);return t<0&&i>0||i<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let i=t||rb.getNormalMatrix(e),s=this.coplanarPoint(bd).applyMatrix4(e),r=this.normal.applyMatrix3(i).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}},ob=0,ws=class extends Fi{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:ob++}),this.uuid=ko(),this.name="",this.type="Material",this.blending=Oo,this.side=ar,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Od,this.blendDst=Fd,this.blendEquation=Lr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new gt(0,0,0),this.blendAlpha=0,this.depthFunc=Eo,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=I0,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=vc,this.stencilZFail=vc,this.stencilZPass=vc,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let i=e[t];if(i===void 0){Ke(`Material: parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){Ke(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(i):s&&s.isVector2&&i&&i.isVector2||s&&s.isEuler&&i&&i.isEuler||s&&s.isVector3&&i&&i.isVector3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(e).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(e).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(e).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(e).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(e).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function s(r){let o=[];for(let a in r){let l=r[a];delete l.metadata,o.push(l)}return o}if(t){let r=s(e.textures),o=s(e.images);r.length>0&&(i.textures=r),o.length>0&&(i.images=o)}return i}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new gt().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(i=>new pi().fromJSON(i))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let i=e.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new ut().fromArray(i)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new ut().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,i=null;if(t!==null){let s=t.length;i=new Array(s);for(let r=0;r!==s;++r)i[r]=t[r].clone()}return this.clippingPlanes=i,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}};var bs=new J,Sd=new J,nc=new J,ic=new J,tr=class{constructor(e=new J,t=new J(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,bs)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let i=t.dot(this.direction);return i<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=bs.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(bs.copy(this.origin).addScaledVector(this.direction,t),bs.distanceToSquared(e))}distanceSqToSegment(e,t,i,s){Sd.copy(e).add(t).multiplyScalar(.5),nc.copy(t).sub(e).normalize(),ic.copy(this.origin).sub(Sd);let r=e.distanceTo(t)*.5,o=-this.direction.dot(nc),a=ic.dot(this.direction),l=-ic.dot(nc),c=ic.lengthSq(),h=Math.abs(1-o*o),d,u,m,g;if(h>0)if(d=o*l-a,u=o*a-l,g=r*h,d>=0)if(u>=-g)if(u<=g){let v=1/h;d*=v,u*=v,m=d*(d+o*u+2*a)+u*(o*d+u+2*l)+c}else u=r,d=Math.max(0,-(o*u+a)),m=-d*d+u*(u+2*l)+c;else u=-r,d=Math.max(0,-(o*u+a)),m=-d*d+u*(u+2*l)+c;else u<=-g?(d=Math.max(0,-(-o*r+a)),u=d>0?-r:Math.min(Math.max(-r,-l),r),m=-d*d+u*(u+2*l)+c):u<=g?(d=0,u=Math.min(Math.max(-r,-l),r),m=u*(u+2*l)+c):(d=Math.max(0,-(o*r+a)),u=d>0?r:Math.min(Math.max(-r,-l),r),m=-d*d+u*(u+2*l)+c);else u=o>0?-r:r,d=Math.max(0,-(o*u+a)),m=-d*d+u*(u+2*l)+c;return i&&i.copy(this.origin).addScaledVector(this.direction,d),s&&s.copy(Sd).addScaledVector(nc,u),m}intersectSphere(e,t){if(e.radius<0)return null;bs.subVectors(e.center,this.origin);let i=bs.dot(this.direction),s=bs.dot(bs)-i*i,r=e.radius*e.radius;if(s>r)return null;let o=Math.sqrt(r-s),a=i-o,l=i+o;return l<0?null:a<0?this.at(l,t):this.at(a,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let i=-(this.origin.dot(e.normal)+e.constant)/t;return i>=0?i:null}intersectPlane(e,t){let i=this.distanceToPlane(e);return i===null?null:this.at(i,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let i,s,r,o,a,l,c=1/this.direction.x,h=1/this.direction.y,d=1/this.direction.z,u=this.origin;return c>=0?(i=(e.min.x-u.x)*c,s=(e.max.x-u.x)*c):(i=(e.max.x-u.x)*c,s=(e.min.x-u.x)*c),h>=0?(r=(e.min.y-u.y)*h,o=(e.max.y-u.y)*h):(r=(e.max.y-u.y)*h,o=(e.min.y-u.y)*h),i>o||r>s||((r>i||isNaN(i))&&(i=r),(o<s||isNaN(s))&&(s=o),d>=0?(a=(e.min.z-u.z)*d,l=(e.max.z-u.z)*d):(a=(e.max.z-u.z)*d,l=(e.min.z-u.z)*d),i>l||a>s)||((a>i||i!==i)&&(i=a),(l<s||s!==s)&&(s=l),s<0)?null:this.at(i>=0?i:s,t)}intersectsBox(e){return this.intersectBox(e,bs)!==null}intersectTriangle(e,t,i,s,r){let o=this.origin,a=this.direction,l=a.x,c=a.y,h=a.z,d=e.x-o.x,u=e.y-o.y,m=e.z-o.z,g=t.x-o.x,v=t.y-o.y,f=t.z-o.z,p=i.x-o.x,x=i.y-o.y,A=i.z-o.z,b=Math.abs(l),C=Math.abs(c),w=Math.abs(h),_,M,U,L,R,z,F,P,B,X,D,ne;if(b>=C&&b>=w?(U=l,z=d,B=g,ne=p,l>=0?(_=c,M=h,L=u,R=m,F=v,P=f,X=x,D=A):(_=h,M=c,L=m,R=u,F=f,P=v,X=A,D=x)):C>=w?(U=c,z=u,B=v,ne=x,c>=0?(_=h,M=l,L=m,R=d,F=f,P=g,X=A,D=p):(_=l,M=h,L=d,R=m,F=g,P=f,X=p,D=A)):(U=h,z=m,B=f,ne=A,h>=0?(_=l,M=c,L=d,R=u,F=g,P=v,X=p,D=x):(_=c,M=l,L=u,R=d,F=v,P=g,X=x,D=p)),U===0)return null;let q=_/U,W=M/U,$=1/U,re=L-q*z,le=R-W*z,Q=F-q*B,me=P-W*B,fe=X-q*ne,ve=D-W*ne,ye=fe*me-ve*Q,Ve=re*ve-le*fe,Je=Q*le-me*re;if(s){if(ye<0||Ve<0||Je<0)return null}else if((ye<0||Ve<0||Je<0)&&(ye>0||Ve>0||Je>0))return null;let Ne=ye+Ve+Je;if(Ne===0)return null;let qe=$*(ye*z+Ve*B+Je*ne);return(Ne>0?qe<0:qe>0)?null:this.at(qe/Ne,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},Dc=class extends ws{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new gt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new js,this.combine=Bd,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}},Vg=new en,Ar=new tr,sc=new er,Wg=new J,rc=new J,oc=new J,ac=new J,Md=new J,lc=new J,Xg=new J,cc=new J,ts=class extends ti{constructor(e=new ni,t=new Dc){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}getVertexPosition(e,t){let i=this.geometry,s=i.attributes.position,r=i.morphAttributes.position,o=i.morphTargetsRelative;t.fromBufferAttribute(s,e);let a=this.morphTargetInfluences;if(r&&a){lc.set(0,0,0);for(let l=0,c=r.length;l<c;l++){let h=a[l],d=r[l];h!==0&&(Md.fromBufferAttribute(d,e),o?lc.addScaledVector(Md,h):lc.addScaledVector(Md.sub(t),h))}t.add(lc)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),sc.copy(i.boundingSphere),sc.applyMatrix4(r),Ar.copy(e.ray).recast(e.near),!(sc.containsPoint(Ar.origin)===!1&&(Ar.intersectSphere(sc,Wg)===null||Ar.origin.distanceToSquared(Wg)>(e.far-e.near)**2))&&(Vg.copy(r).invert(),Ar.copy(e.ray).applyMatrix4(Vg),!(i.boundingBox!==null&&Ar.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(e,t,Ar)))}_computeIntersections(e,t,i){let s,r=this.geometry,o=this.material,a=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,d=r.attributes.normal,u=r.groups,m=r.drawRange;if(a!==null)if(Array.isArray(o))for(let g=0,v=u.length;g<v;g++){let f=u[g],p=o[f.materialIndex],x=Math.max(f.start,m.start),A=Math.min(a.count,Math.min(f.start+f.count,m.start+m.count));for(let b=x,C=A;b<C;b+=3){let w=a.getX(b),_=a.getX(b+1),M=a.getX(b+2);s=hc(this,p,e,i,c,h,d,w,_,M),s&&(s.faceIndex=Math.floor(b/3),s.face.materialIndex=f.materialIndex,t.push(s))}}else{let g=Math.max(0,m.start),v=Math.min(a.count,m.start+m.count);for(let f=g,p=v;f<p;f+=3){let x=a.getX(f),A=a.getX(f+1),b=a.getX(f+2);s=hc(this,o,e,i,c,h,d,x,A,b),s&&(s.faceIndex=Math.floor(f/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(o))for(let g=0,v=u.length;g<v;g++){let f=u[g],p=o[f.materialIndex],x=Math.max(f.start,m.start),A=Math.min(l.count,Math.min(f.start+f.count,m.start+m.count));for(let b=x,C=A;b<C;b+=3){let w=b,_=b+1,M=b+2;s=hc(this,p,e,i,c,h,d,w,_,M),s&&(s.faceIndex=Math.floor(b/3),s.face.materialIndex=f.materialIndex,t.push(s))}}else{let g=Math.max(0,m.start),v=Math.min(l.count,m.start+m.count);for(let f=g,p=v;f<p;f+=3){let x=f,A=f+1,b=f+2;s=hc(this,o,e,i,c,h,d,x,A,b),s&&(s.faceIndex=Math.floor(f/3),t.push(s))}}}};function ab(n,e,t,i,s,r,o,a){let l;if(e.side===jn?l=i.intersectTriangle(o,r,s,!0,a):l=i.intersectTriangle(s,r,o,e.side===ar,a),l===null)return null;cc.copy(a),cc.applyMatrix4(n.matrixWorld);let c=t.ray.origin.distanceTo(cc);return c<t.near||c>t.far?null:{distance:c,point:cc.clone(),object:n}}function hc(n,e,t,i,s,r,o,a,l,c){n.getVertexPosition(a,rc),n.getVertexPosition(l,oc),n.getVertexPosition(c,ac);let h=ab(n,e,t,i,rc,oc,ac,Xg);if(h){let d=new J;Js.getBarycoord(Xg,rc,oc,ac,d),s&&(h.uv=Js.getInterpolatedAttribute(s,a,l,c,d,new ut)),r&&(h.uv1=Js.getInterpolatedAttribute(r,a,l,c,d,new ut)),o&&(h.normal=Js.getInterpolatedAttribute(o,a,l,c,d,new J),h.normal.dot(i.direction)>0&&h.normal.multiplyScalar(-1));let u={a,b:l,c,normal:new J,materialIndex:0};Js.getNormal(rc,oc,ac,u.normal),h.face=u,h.barycoord=d}return h}var Uc=class extends ei{constructor(e=null,t=1,i=1,s,r,o,a,l,c=Dn,h=Dn,d,u){super(null,o,a,l,c,h,s,r,d,u),this.isDataTexture=!0,this.image={data:e,width:t,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var Rr=new er,lb=new ut(.5,.5),uc=new J,Ir=class{constructor(e=new pi,t=new pi,i=new pi,s=new pi,r=new pi,o=new pi){this.planes=[e,t,i,s,r,o]}set(e,t,i,s,r,o){let a=this.planes;return a[0].copy(e),a[1].copy(t),a[2].copy(i),a[3].copy(s),a[4].copy(r),a[5].copy(o),this}copy(e){let t=this.planes;for(let i=0;i<6;i++)t[i].copy(e.planes[i]);return this}setFromProjectionMatrix(e,t=Ti,i=!1){let s=this.planes,r=e.elements,o=r[0],a=r[1],l=r[2],c=r[3],h=r[4],d=r[5],u=r[6],m=r[7],g=r[8],v=r[9],f=r[10],p=r[11],x=r[12],A=r[13],b=r[14],C=r[15];if(s[0].setComponents(c-o,m-h,p-g,C-x).normalize(),s[1].setComponents(c+o,m+h,p+g,C+x).normalize(),s[2].setComponents(c+a,m+d,p+v,C+A).normalize(),s[3].setComponents(c-a,m-d,p-v,C-A).normalize(),i)s[4].setComponents(l,u,f,b).normalize(),s[5].setComponents(c-l,m-u,p-f,C-b).normalize();else if(s[4].setComponents(c-l,m-u,p-f,C-b).normalize(),t===Ti)s[5].setComponents(c+l,m+u,p+f,C+b).normalize();else if(t===Ta)s[5].setComponents(l,u,f,b).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Rr.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Rr.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Rr)}intersectsSprite(e){Rr.center.set(0,0,0);let t=lb.distanceTo(e.center);return Rr.radius=.7071067811865476+t,Rr.applyMatrix4(e.matrixWorld),this.intersectsSphere(Rr)}intersectsSphere(e){let t=this.planes,i=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(i)<s)return!1;return!0}intersectsBox(e){let t=this.planes;for(let i=0;i<6;i++){let s=t[i];if(uc.x=s.normal.x>0?e.max.x:e.min.x,uc.y=s.normal.y>0?e.max.y:e.min.y,uc.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(uc)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let i=0;i<6;i++)if(t[i].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},$g=new en,Oc=class n{constructor(){this.coordinateSystem=Ti,this._frustums=[],this._count=0}setFromArrayCamera(e){let t=e.cameras,i=this._frustums;for(let s=0;s<t.length;s++){let r=t[s];$g.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),i[s]===void 0&&(i[s]=new Ir),i[s].setFromProjectionMatrix($g,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsObject(e))return!0;return!1}intersectsSprite(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSprite(e))return!0;return!1}intersectsSphere(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSphere(e))return!0;return!1}intersectsBox(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsBox(e))return!0;return!1}containsPoint(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;let t=this._frustums,i=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Ir),t[s].copy(i[s]);return this._count=e._count,this}clone(){return new n().copy(this)}};var Io=class extends ws{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new gt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}},Fc=new J,Bc=new J,qg=new en,xa=new tr,dc=new er,wd=new J,Yg=new J,kc=class extends ti{constructor(e=new ni,t=new Io){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[0];for(let s=1,r=t.count;s<r;s++)Fc.fromBufferAttribute(t,s-1),Bc.fromBufferAttribute(t,s),i[s]=i[s-1],i[s]+=Fc.distanceTo(Bc);e.setAttribute("lineDistance",new Nn(i,1))}else Ke("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),dc.copy(i.boundingSphere),dc.applyMatrix4(s),dc.radius+=r,e.ray.intersectsSphere(dc)===!1)return;qg.copy(s).invert(),xa.copy(e.ray).applyMatrix4(qg);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=this.isLineSegments?2:1,h=i.index,u=i.attributes.position;if(h!==null){let m=Math.max(0,o.start),g=Math.min(h.count,o.start+o.count);for(let v=m,f=g-1;v<f;v+=c){let p=h.getX(v),x=h.getX(v+1),A=fc(this,e,xa,l,p,x,v);A&&t.push(A)}if(this.isLineLoop){let v=h.getX(g-1),f=h.getX(m),p=fc(this,e,xa,l,v,f,g-1);p&&t.push(p)}}else{let m=Math.max(0,o.start),g=Math.min(u.count,o.start+o.count);for(let v=m,f=g-1;v<f;v+=c){let p=fc(this,e,xa,l,v,v+1,v);p&&t.push(p)}if(this.isLineLoop){let v=fc(this,e,xa,l,g-1,m,g-1);v&&t.push(v)}}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function fc(n,e,t,i,s,r,o){let a=n.geometry.attributes.position;if(Fc.fromBufferAttribute(a,s),Bc.fromBufferAttribute(a,r),t.distanceSqToSegment(Fc,Bc,wd,Yg)>i)return;wd.applyMatrix4(n.matrixWorld);let c=e.ray.origin.distanceTo(wd);if(!(c<e.near||c>e.far))return{distance:c,point:Yg.clone().applyMatrix4(n.matrixWorld),index:o,face:null,faceIndex:null,barycoord:null,object:n}}var Zg=new J,Kg=new J,Na=class extends kc{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[];for(let s=0,r=t.count;s<r;s+=2)Zg.fromBufferAttribute(t,s),Kg.fromBufferAttribute(t,s+1),i[s]=s===0?0:i[s-1],i[s+1]=i[s]+Zg.distanceTo(Kg);e.setAttribute("lineDistance",new Nn(i,1))}else Ke("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}};var Po=class extends ws{constructor(e){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new gt(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.size=e.size,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}},Jg=new en,Cd=new tr,pc=new er,mc=new J,Da=class extends ti{constructor(e=new ni,t=new Po){super(),this.isPoints=!0,this.type="Points",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Points.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),pc.copy(i.boundingSphere),pc.applyMatrix4(s),pc.radius+=r,e.ray.intersectsSphere(pc)===!1)return;Jg.copy(s).invert(),Cd.copy(e.ray).applyMatrix4(Jg);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=i.index,d=i.attributes.position;if(c!==null){let u=Math.max(0,o.start),m=Math.min(c.count,o.start+o.count);for(let g=u,v=m;g<v;g++){let f=c.getX(g);mc.fromBufferAttribute(d,f),jg(mc,f,l,s,e,t,this)}}else{let u=Math.max(0,o.start),m=Math.min(d.count,o.start+o.count);for(let g=u,v=m;g<v;g++)mc.fromBufferAttribute(d,g),jg(mc,g,l,s,e,t,this)}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function jg(n,e,t,i,s,r,o){let a=Cd.distanceSqToPoint(n);if(a<t){let l=new J;Cd.closestPointToPoint(n,l),l.applyMatrix4(i);let c=s.ray.origin.distanceTo(l);if(c<s.near||c>s.far)return;r.push({distance:c,distanceToRay:Math.sqrt(a),point:l,index:e,face:null,faceIndex:null,barycoord:null,object:o})}}var Ua=class extends ei{constructor(e=[],t=Nr,i,s,r,o,a,l,c,h){super(e,t,i,s,r,o,a,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}};var Es=class extends ei{constructor(e,t,i=Bi,s,r,o,a=Dn,l=Dn,c,h=Ms,d=1){if(h!==Ms&&h!==As)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let u={width:e,height:t,depth:d};super(u,s,r,o,a,l,h,i,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Ro(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}},Oa=class extends Es{constructor(e,t=Bi,i=Nr,s,r,o=Dn,a=Dn,l,c=Ms){let h={width:e,height:e,depth:1},d=[h,h,h,h,h,h];super(e,e,t,i,s,r,o,a,l,c),this.image=d,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}},Fa=class extends ei{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}},Lo=class n extends ni{constructor(e=1,t=1,i=1,s=1,r=1,o=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:i,widthSegments:s,heightSegments:r,depthSegments:o};let a=this;s=Math.floor(s),r=Math.floor(r),o=Math.floor(o);let l=[],c=[],h=[],d=[],u=0,m=0;g("z","y","x",-1,-1,i,t,e,o,r,0),g("z","y","x",1,-1,i,t,-e,o,r,1),g("x","z","y",1,1,e,i,t,s,o,2),g("x","z","y",1,-1,e,i,-t,s,o,3),g("x","y","z",1,-1,e,t,i,s,r,4),g("x","y","z",-1,-1,e,t,-i,s,r,5),this.setIndex(l),this.setAttribute("position",new Nn(c,3)),this.setAttribute("normal",new Nn(h,3)),this.setAttribute("uv",new Nn(d,2));function g(v,f,p,x,A,b,C,w,_,M,U){let L=b/_,R=C/M,z=b/2,F=C/2,P=w/2,B=_+1,X=M+1,D=0,ne=0,q=new J;for(let W=0;W<X;W++){let $=W*R-F;for(let re=0;re<B;re++){let le=re*L-z;q[v]=le*x,q[f]=$*A,q[p]=P,c.push(q.x,q.y,q.z),q[v]=0,q[f]=0,q[p]=w>0?1:-1,h.push(q.x,q.y,q.z),d.push(re/_),d.push(1-W/M),D+=1}}for(let W=0;W<M;W++)for(let $=0;$<_;$++){let re=u+$+B*W,le=u+$+B*(W+1),Q=u+($+1)+B*(W+1),me=u+($+1)+B*W;l.push(re,le,me),l.push(le,Q,me),ne+=6}a.addGroup(m,ne,U),m+=ne,u+=D}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};var Ba=class n extends ni{constructor(e=1,t=1,i=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:i,heightSegments:s};let r=e/2,o=t/2,a=Math.floor(i),l=Math.floor(s),c=a+1,h=l+1,d=e/a,u=t/l,m=[],g=[],v=[],f=[];for(let p=0;p<h;p++){let x=p*u-o;for(let A=0;A<c;A++){let b=A*d-r;g.push(b,-x,0),v.push(0,0,1),f.push(A/a),f.push(1-p/l)}}for(let p=0;p<l;p++)for(let x=0;x<a;x++){let A=x+c*p,b=x+c*(p+1),C=x+1+c*(p+1),w=x+1+c*p;m.push(A,b,w),m.push(b,C,w)}this.setIndex(m),this.setAttribute("position",new Nn(g,3)),this.setAttribute("normal",new Nn(v,3)),this.setAttribute("uv",new Nn(f,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.widthSegments,e.heightSegments)}};function Ur(n){let e={};for(let t in n){e[t]={};for(let i in n[t]){let s=n[t][i];if(Qg(s))s.isRenderTargetTexture?(Ke("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][i]=null):e[t][i]=s.clone();else if(Array.isArray(s))if(Qg(s[0])){let r=[];for(let o=0,a=s.length;o<a;o++)r[o]=s[o].clone();e[t][i]=r}else e[t][i]=s.slice();else e[t][i]=s}}return e}function Vn(n){let e={};for(let t=0;t<n.length;t++){let i=Ur(n[t]);for(let s in i)e[s]=i[s]}return e}function Qg(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function cb(n){let e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function uf(n){let e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:Tt.workingColorSpace}var W0={clone:Ur,merge:Vn},hb=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,ub=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,ns=class extends ws{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=hb,this.fragmentShader=ub,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Ur(e.uniforms),this.uniformsGroups=cb(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let s in this.uniforms){let o=this.uniforms[s].value;o&&o.isTexture?t.uniforms[s]={type:"t",value:o.toJSON(e).uuid}:o&&o.isColor?t.uniforms[s]={type:"c",value:o.getHex()}:o&&o.isVector2?t.uniforms[s]={type:"v2",value:o.toArray()}:o&&o.isVector3?t.uniforms[s]={type:"v3",value:o.toArray()}:o&&o.isVector4?t.uniforms[s]={type:"v4",value:o.toArray()}:o&&o.isMatrix3?t.uniforms[s]={type:"m3",value:o.toArray()}:o&&o.isMatrix4?t.uniforms[s]={type:"m4",value:o.toArray()}:t.uniforms[s]={value:o}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let i={};for(let s in this.extensions)this.extensions[s]===!0&&(i[s]=!0);return Object.keys(i).length>0&&(t.extensions=i),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(let i in e.uniforms){let s=e.uniforms[i];switch(this.uniforms[i]={},s.type){case"t":this.uniforms[i].value=t[s.value]||null;break;case"c":this.uniforms[i].value=new gt().setHex(s.value);break;case"v2":this.uniforms[i].value=new ut().fromArray(s.value);break;case"v3":this.uniforms[i].value=new J().fromArray(s.value);break;case"v4":this.uniforms[i].value=new sn().fromArray(s.value);break;case"m3":this.uniforms[i].value=new at().fromArray(s.value);break;case"m4":this.uniforms[i].value=new en().fromArray(s.value);break;default:this.uniforms[i].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(let i in e.extensions)this.extensions[i]=e.extensions[i];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}},zc=class extends ns{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}};var Gc=class extends ws{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=R0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},Hc=class extends ws{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}};function bo(n,e){return!n||n.constructor===e?n:typeof e.BYTES_PER_ELEMENT=="number"?new e(n):Array.prototype.slice.call(n)}function gc(n){return n!==void 0&&n.inTangents!==void 0&&n.outTangents!==void 0}var nr=class{constructor(e,t,i,s){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=s!==void 0?s:new t.constructor(i),this.sampleValues=t,this.valueSize=i,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,i=this._cachedIndex,s=t[i],r=t[i-1];n:{e:{let o;t:{i:if(!(e<s)){for(let a=i+2;;){if(s===void 0){if(e<r)break i;return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}if(i===a)break;if(r=s,s=t[++i],e<s)break e}o=t.length;break t}if(!(e>=r)){let a=t[1];e<a&&(i=2,r=a);for(let l=i-2;;){if(r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(i===l)break;if(s=r,r=t[--i-1],e>=r)break e}o=i,i=0;break t}break n}for(;i<o;){let a=i+o>>>1;e<t[a]?o=a:i=a+1}if(s=t[i],r=t[i-1],r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(s===void 0)return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}this._cachedIndex=i,this.intervalChanged_(i,r,s)}return this.interpolate_(i,r,e,s)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,i=this.sampleValues,s=this.valueSize,r=e*s;for(let o=0;o!==s;++o)t[o]=i[r+o];return t}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},Vc=class extends nr{constructor(e,t,i,s){super(e,t,i,s),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:Td,endingEnd:Td}}intervalChanged_(e,t,i){let s=this.parameterPositions,r=e-2,o=e+1,a=s[r],l=s[o];if(a===void 0)switch(this.getSettings_().endingStart){case Ad:r=e,a=2*t-i;break;case Rd:r=s.length-2,a=t+s[r]-s[r+1];break;default:r=e,a=i}if(l===void 0)switch(this.getSettings_().endingEnd){case Ad:o=e,l=2*i-t;break;case Rd:o=1,l=i+s[1]-s[0];break;default:o=e-1,l=t}let c=(i-t)*.5,h=this.valueSize;this._weightPrev=c/(t-a),this._weightNext=c/(l-i),this._offsetPrev=r*h,this._offsetNext=o*h}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=this._offsetPrev,d=this._offsetNext,u=this._weightPrev,m=this._weightNext,g=(i-t)/(s-t),v=g*g,f=v*g,p=-u*f+2*u*v-u*g,x=(1+u)*f+(-1.5-2*u)*v+(-.5+u)*g+1,A=(-1-m)*f+(1.5+m)*v+.5*g,b=m*f-m*v;for(let C=0;C!==a;++C)r[C]=p*o[h+C]+x*o[c+C]+A*o[l+C]+b*o[d+C];return r}},Wc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=(i-t)/(s-t),d=1-h;for(let u=0;u!==a;++u)r[u]=o[c+u]*d+o[l+u]*h;return r}},Xc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e){return this.copySampleValue_(e-1)}},$c=class extends nr{interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=this.inTangents,d=this.outTangents;if(!h||!d){let g=(i-t)/(s-t),v=1-g;for(let f=0;f!==a;++f)r[f]=o[c+f]*v+o[l+f]*g;return r}let u=a*2,m=e-1;for(let g=0;g!==a;++g){let v=o[c+g],f=o[l+g],p=m*u+g*2,x=d[p],A=d[p+1],b=e*u+g*2,C=h[b],w=h[b+1],_=fb(i,t,x,C,s);r[g]=X0(_,v,A,w,f)}return r}};function X0(n,e,t,i,s){let r=1-n;return r*r*r*e+3*r*r*n*t+3*r*n*n*i+n*n*n*s}function db(n,e,t,i,s){let r=1-n;return 3*r*r*(t-e)+6*r*n*(i-t)+3*n*n*(s-i)}function fb(n,e,t,i,s){let r=(n-e)/(s-e);for(let o=0;o<8;o++){let a=X0(r,e,t,i,s)-n;if(Math.abs(a)<1e-10)break;let l=db(r,e,t,i,s);if(Math.abs(l)<1e-10)break;r=Math.max(0,Math.min(1,r-a/l))}return r}var yi=class{constructor(e,t,i,s){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=bo(t,this.TimeBufferType),this.values=bo(i,this.ValueBufferType),this.setInterpolation(s||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,i;if(t.toJSON!==this.toJSON)i=t.toJSON(e);else{i={name:e.name,times:bo(e.times,Array),values:bo(e.values,Array)};let s=e.getInterpolation();s!==e.DefaultInterpolation&&(i.interpolation=s),gc(e.settings)&&(i.settings={inTangents:bo(e.settings.inTangents,Array),outTangents:bo(e.settings.outTangents,Array)})}return i.type=e.ValueTypeName,i}InterpolantFactoryMethodDiscrete(e){return new Xc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new Wc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new Vc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodBezier(e){let t=new $c(this.times,this.values,this.getValueSize(),e);return this.settings&&(t.inTangents=this.settings.inTangents,t.outTangents=this.settings.outTangents),t}setInterpolation(e){let t;switch(e){case Ma:t=this.InterpolantFactoryMethodDiscrete;break;case Ic:t=this.InterpolantFactoryMethodLinear;break;case xc:t=this.InterpolantFactoryMethodSmooth;break;case Ed:t=this.InterpolantFactoryMethodBezier;break}if(t===void 0){let i="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(i);return Ke("KeyframeTrack:",i),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return Ma;case this.InterpolantFactoryMethodLinear:return Ic;case this.InterpolantFactoryMethodSmooth:return xc;case this.InterpolantFactoryMethodBezier:return Ed}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]+=e;gc(this.settings)&&(e0(this.settings.inTangents,e),e0(this.settings.outTangents,e))}return this}scale(e){if(e!==1){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]*=e;gc(this.settings)&&(t0(this.settings.inTangents,e),t0(this.settings.outTangents,e))}return this}trim(e,t){let i=this.times,s=i.length,r=0,o=s-1;for(;r!==s&&i[r]<e;)++r;for(;o!==-1&&i[o]>t;)--o;if(++o,r!==0||o!==s){r>=o&&(o=Math.max(o,1),r=o-1);let a=this.getValueSize();this.times=i.slice(r,o),this.values=this.values.slice(r*a,o*a)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(ot("KeyframeTrack: Invalid value size in track.",this),e=!1);let i=this.times,s=this.values,r=i.length;r===0&&(ot("KeyframeTrack: Track is empty.",this),e=!1);let o=null;for(let a=0;a!==r;a++){let l=i[a];if(typeof l=="number"&&isNaN(l)){ot("KeyframeTrack: Time is not a valid number.",this,a,l),e=!1;break}if(o!==null&&o>l){ot("KeyframeTrack: Out of order keys.",this,a,l,o),e=!1;break}o=l}if(s!==void 0&&Cv(s))for(let a=0,l=s.length;a!==l;++a){let c=s[a];if(isNaN(c)){ot("KeyframeTrack: Value is not a valid number.",this,a,c),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),i=this.getValueSize(),s=this.getInterpolation()===xc,r=e.length-1,o=1;for(let a=1;a<r;++a){let l=!1,c=e[a],h=e[a+1];if(c!==h&&(a!==1||c!==e[0]))if(s)l=!0;else{let d=a*i,u=d-i,m=d+i;for(let g=0;g!==i;++g){let v=t[d+g];if(v!==t[u+g]||v!==t[m+g]){l=!0;break}}}if(l){if(a!==o){e[o]=e[a];let d=a*i,u=o*i;for(let m=0;m!==i;++m)t[u+m]=t[d+m]}++o}}if(r>0){e[o]=e[r];for(let a=r*i,l=o*i,c=0;c!==i;++c)t[l+c]=t[a+c];++o}return o!==e.length?(this.times=e.slice(0,o),this.values=t.slice(0,o*i)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),i=this.constructor,s=new i(this.name,e,t);return s.createInterpolant=this.createInterpolant,gc(this.settings)&&(s.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),s}};function e0(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]+=e}function t0(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]*=e}yi.prototype.ValueTypeName="";yi.prototype.TimeBufferType=Float32Array;yi.prototype.ValueBufferType=Float32Array;yi.prototype.DefaultInterpolation=Ic;var ir=class extends yi{constructor(e,t,i){super(e,t,i)}};ir.prototype.ValueTypeName="bool";ir.prototype.ValueBufferType=Array;ir.prototype.DefaultInterpolation=Ma;ir.prototype.InterpolantFactoryMethodLinear=void 0;ir.prototype.InterpolantFactoryMethodSmooth=void 0;var qc=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}};qc.prototype.ValueTypeName="color";var Yc=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}};Yc.prototype.ValueTypeName="number";var Zc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=(i-t)/(s-t),c=e*a;for(let h=c+a;c!==h;c+=4)gi.slerpFlat(r,0,o,c-a,o,c,l);return r}},ka=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}InterpolantFactoryMethodLinear(e){return new Zc(this.times,this.values,this.getValueSize(),e)}};ka.prototype.ValueTypeName="quaternion";ka.prototype.InterpolantFactoryMethodSmooth=void 0;var sr=class extends yi{constructor(e,t,i){super(e,t,i)}};sr.prototype.ValueTypeName="string";sr.prototype.ValueBufferType=Array;sr.prototype.DefaultInterpolation=Ma;sr.prototype.InterpolantFactoryMethodLinear=void 0;sr.prototype.InterpolantFactoryMethodSmooth=void 0;var Kc=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}};Kc.prototype.ValueTypeName="vector";var Jc=class{constructor(e,t,i){let s=this,r=!1,o=0,a=0,l,c=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=i,this._abortController=null,this.itemStart=function(h){a++,r===!1&&s.onStart!==void 0&&s.onStart(h,o,a),r=!0},this.itemEnd=function(h){o++,s.onProgress!==void 0&&s.onProgress(h,o,a),o===a&&(r=!1,s.onLoad!==void 0&&s.onLoad())},this.itemError=function(h){s.onError!==void 0&&s.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),l?l(h):h},this.setURLModifier=function(h){return l=h,this},this.addHandler=function(h,d){return c.push(h,d),this},this.removeHandler=function(h){let d=c.indexOf(h);return d!==-1&&c.splice(d,2),this},this.getHandler=function(h){for(let d=0,u=c.length;d<u;d+=2){let m=c[d],g=c[d+1];if(m.global&&(m.lastIndex=0),m.test(h))return g}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},$0=new Jc,jc=class{constructor(e){this.manager=e!==void 0?e:$0,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(e,t){let i=this;return new Promise(function(s,r){i.load(e,s,t,r)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}setPriority(e){return this.priority=e,this}setCache(e){return this.cache=e,this}abort(){return this}};jc.DEFAULT_MATERIAL_NAME="__DEFAULT";var _c=new J,yc=new gi,Qi=new J,za=class extends ti{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new en,this.projectionMatrix=new en,this.projectionMatrixInverse=new en,this.coordinateSystem=Ti,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(_c,yc,Qi),Qi.x===1&&Qi.y===1&&Qi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(_c,yc,Qi.set(1,1,1)).invert()}updateWorldMatrix(e,t,i=!1){super.updateWorldMatrix(e,t,i),this.matrixWorld.decompose(_c,yc,Qi),Qi.x===1&&Qi.y===1&&Qi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(_c,yc,Qi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},Ks=new J,n0=new ut,i0=new ut,Kn=class extends za{constructor(e=50,t=1,i=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=i,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=Ao*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(ba*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Ao*2*Math.atan(Math.tan(ba*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,i){Ks.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(Ks.x,Ks.y).multiplyScalar(-e/Ks.z),Ks.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set(Ks.x,Ks.y).multiplyScalar(-e/Ks.z)}getViewSize(e,t){return this.getViewBounds(e,n0,i0),t.subVectors(i0,n0)}setViewOffset(e,t,i,s,r,o){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(ba*.5*this.fov)/this.zoom,i=2*t,s=this.aspect*i,r=-.5*s,o=this.view;if(this.view!==null&&this.view.enabled){let l=o.fullWidth,c=o.fullHeight;r+=o.offsetX*s/l,t-=o.offsetY*i/c,s*=o.width/l,i*=o.height/c}let a=this.filmOffset;a!==0&&(r+=e*a/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-i,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}};var Qc=class extends za{constructor(e=-1,t=1,i=1,s=-1,r=.1,o=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=i,this.bottom=s,this.near=r,this.far=o,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,i,s,r,o){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,s=(this.top+this.bottom)/2,r=i-e,o=i+e,a=s+t,l=s-t;if(this.view!==null&&this.view.enabled){let c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,o=r+c*this.view.width,a-=h*this.view.offsetY,l=a-h*this.view.height}this.projectionMatrix.makeOrthographic(r,o,a,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}};var So=-90,Mo=1,No=class extends ti{constructor(e,t,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;let s=new Kn(So,Mo,e,t);s.layers=this.layers,this.add(s);let r=new Kn(So,Mo,e,t);r.layers=this.layers,this.add(r);let o=new Kn(So,Mo,e,t);o.layers=this.layers,this.add(o);let a=new Kn(So,Mo,e,t);a.layers=this.layers,this.add(a);let l=new Kn(So,Mo,e,t);l.layers=this.layers,this.add(l);let c=new Kn(So,Mo,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[i,s,r,o,a,l]=t;for(let c of t)this.remove(c);if(e===Ti)i.up.set(0,1,0),i.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),o.up.set(0,0,1),o.lookAt(0,-1,0),a.up.set(0,1,0),a.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Ta)i.up.set(0,-1,0),i.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),o.up.set(0,0,-1),o.lookAt(0,-1,0),a.up.set(0,-1,0),a.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:i,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[r,o,a,l,c,h]=this.children,d=e.getRenderTarget(),u=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),g=e.xr.enabled;e.xr.enabled=!1;let v=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let f=!1;e.isWebGLRenderer===!0?f=e.state.buffers.depth.getReversed():f=e.reversedDepthBuffer,e.setRenderTarget(i,0,s),f&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(i,1,s),f&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(i,2,s),f&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(i,3,s),f&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(i,4,s),f&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),i.texture.mipmapsAutoUpdate=v,e.setRenderTarget(i,5,s),f&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(d,u,m),e.xr.enabled=g,i.texture.needsPMREMUpdate=!0}},eh=class extends Kn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}};var df="\\[\\]\\.:\\/",pb=new RegExp("["+df+"]","g"),ff="[^"+df+"]",mb="[^"+df.replace("\\.","")+"]",gb=/((?:WC+[\/:])*)/.source.replace("WC",ff),_b=/(WCOD+)?/.source.replace("WCOD",mb),yb=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",ff),xb=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",ff),vb=new RegExp("^"+gb+_b+yb+xb+"$"),bb=["material","materials","bones","map"],Id=class{constructor(e,t,i){let s=i||jt.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,s)}getValue(e,t){this.bind();let i=this._targetGroup.nCachedObjects_,s=this._bindings[i];s!==void 0&&s.getValue(e,t)}setValue(e,t){let i=this._bindings;for(let s=this._targetGroup.nCachedObjects_,r=i.length;s!==r;++s)i[s].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].unbind()}},jt=class n{constructor(e,t,i){this.path=t,this.parsedPath=i||n.parseTrackName(t),this.node=n.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,i){return e&&e.isAnimationObjectGroup?new n.Composite(e,t,i):new n(e,t,i)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(pb,"")}static parseTrackName(e){let t=vb.exec(e);if(t===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+e);let i={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},s=i.nodeName&&i.nodeName.lastIndexOf(".");if(s!==void 0&&s!==-1){let r=i.nodeName.substring(s+1);bb.indexOf(r)!==-1&&(i.nodeName=i.nodeName.substring(0,s),i.objectName=r)}if(i.propertyName===null||i.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+e);return i}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let i=e.skeleton.getBoneByName(t);if(i!==void 0)return i}if(e.children){let i=function(r){for(let o=0;o<r.length;o++){let a=r[o];if(a.name===t||a.uuid===t)return a;let l=i(a.children);if(l)return l}return null},s=i(e.children);if(s)return s}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)e[t++]=i[s]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,i=t.objectName,s=t.propertyName,r=t.propertyIndex;if(e||(e=n.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){Ke("PropertyBinding: No target node found for track: "+this.path+".");return}if(i){let c=t.objectIndex;switch(i){case"materials":if(!e.material){ot("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){ot("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){ot("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let h=0;h<e.length;h++)if(e[h].name===c){c=h;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){ot("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){ot("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[i]===void 0){ot("PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[i]}if(c!==void 0){if(e[c]===void 0){ot("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[c]}}let o=e[s];if(o===void 0){let c=t.nodeName;ot("PropertyBinding: Trying to update property for track: "+c+"."+s+" but it wasn't found.",e);return}let a=this.Versioning.None;this.targetObject=e,e.isMaterial===!0?a=this.Versioning.NeedsUpdate:e.isObject3D===!0&&(a=this.Versioning.MatrixWorldNeedsUpdate);let l=this.BindingType.Direct;if(r!==void 0){if(s==="morphTargetInfluences"){if(!e.geometry){ot("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){ot("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[r]!==void 0&&(r=e.morphTargetDictionary[r])}l=this.BindingType.ArrayElement,this.resolvedProperty=o,this.propertyIndex=r}else o.fromArray!==void 0&&o.toArray!==void 0?(l=this.BindingType.HasFromToArray,this.resolvedProperty=o):Array.isArray(o)?(l=this.BindingType.EntireArray,this.resolvedProperty=o):this.propertyName=s;this.getValue=this.GetterByBindingType[l],this.setValue=this.SetterByBindingTypeAndVersioning[l][a]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};jt.Composite=Id;jt.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};jt.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};jt.prototype.GetterByBindingType=[jt.prototype._getValue_direct,jt.prototype._getValue_array,jt.prototype._getValue_arrayElement,jt.prototype._getValue_toArray];jt.prototype.SetterByBindingTypeAndVersioning=[[jt.prototype._setValue_direct,jt.prototype._setValue_direct_setNeedsUpdate,jt.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[jt.prototype._setValue_array,jt.prototype._setValue_array_setNeedsUpdate,jt.prototype._setValue_array_setMatrixWorldNeedsUpdate],[jt.prototype._setValue_arrayElement,jt.prototype._setValue_arrayElement_setNeedsUpdate,jt.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[jt.prototype._setValue_fromArray,jt.prototype._setValue_fromArray_setNeedsUpdate,jt.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var pR=new Float32Array(1);var Do=class{constructor(e=1,t=0,i=0){this.radius=e,this.phi=t,this.theta=i}set(e,t,i){return this.radius=e,this.phi=t,this.theta=i,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=bt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,i){return this.radius=Math.sqrt(e*e+t*t+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,i),this.phi=Math.acos(bt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var xf=class xf{constructor(e,t,i,s){this.elements=[1,0,0,1],e!==void 0&&this.set(e,t,i,s)}identity(){return this.set(1,0,0,1),this}fromArray(e,t=0){for(let i=0;i<4;i++)this.elements[i]=e[i+t];return this}set(e,t,i,s){let r=this.elements;return r[0]=e,r[2]=t,r[1]=i,r[3]=s,this}};xf.prototype.isMatrix2=!0;var Pd=xf;var Ga=class extends Na{constructor(e=10,t=10,i=4473924,s=8947848){i=new gt(i),s=new gt(s);let r=t/2,o=e/t,a=e/2,l=[],c=[];for(let u=0,m=0,g=-a;u<=t;u++,g+=o){l.push(-a,0,g,a,0,g),l.push(g,0,-a,g,0,a);let v=u===r?i:s;v.toArray(c,m),m+=3,v.toArray(c,m),m+=3,v.toArray(c,m),m+=3,v.toArray(c,m),m+=3}let h=new ni;h.setAttribute("position",new Nn(l,3)),h.setAttribute("color",new Nn(c,3));let d=new Io({vertexColors:!0,toneMapped:!1});super(h,d),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Ha=class extends Na{constructor(e=1){let t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],i=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new ni;s.setAttribute("position",new Nn(t,3)),s.setAttribute("color",new Nn(i,3));let r=new Io({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,i){let s=new gt,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(i),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Va=class extends Fi{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function pf(n,e,t,i){let s=Sb(i);switch(t){case Jd:return n*e;case Qd:return n*e/s.components*s.byteLength;case lh:return n*e/s.components*s.byteLength;case lr:return n*e*2/s.components*s.byteLength;case ch:return n*e*2/s.components*s.byteLength;case jd:return n*e*3/s.components*s.byteLength;case Gi:return n*e*4/s.components*s.byteLength;case hh:return n*e*4/s.components*s.byteLength;case $a:case qa:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Ya:case Za:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case dh:case ph:return Math.max(n,16)*Math.max(e,8)/4;case uh:case fh:return Math.max(n,8)*Math.max(e,8)/2;case mh:case gh:case yh:case xh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case _h:case Ka:case vh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case bh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Sh:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case Mh:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case wh:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case Eh:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case Th:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case Ah:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case Rh:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case Ch:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case Ih:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case Ph:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case Lh:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case Nh:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case Dh:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case Uh:case Oh:case Fh:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Bh:case kh:return Math.ceil(n/4)*Math.ceil(e/4)*8;case Ja:case zh:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function Sb(n){switch(n){case xi:case qd:return{byteLength:1,components:1};case Bo:case Yd:case zi:return{byteLength:2,components:1};case oh:case ah:return{byteLength:2,components:4};case Bi:case rh:case ki:return{byteLength:4,components:1};case Zd:case Kd:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?Ke("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187");function p_(){let n=null,e=!1,t=null,i=null;function s(r,o){i=n.requestAnimationFrame(s),t(r,o)}return{start:function(){e!==!0&&t!==null&&n!==null&&(i=n.requestAnimationFrame(s),e=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){n=r}}}function wb(n){let e=new WeakMap;function t(a,l){let c=a.array,h=a.usage,d=c.byteLength,u=n.createBuffer();n.bindBuffer(l,u),n.bufferData(l,c,h),a.onUploadCallback();let m;if(c instanceof Float32Array)m=n.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=n.HALF_FLOAT;else if(c instanceof Uint16Array)a.isFloat16BufferAttribute?m=n.HALF_FLOAT:m=n.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=n.SHORT;else if(c instanceof Uint32Array)m=n.UNSIGNED_INT;else if(c instanceof Int32Array)m=n.INT;else if(c instanceof Int8Array)m=n.BYTE;else if(c instanceof Uint8Array)m=n.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:u,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:a.version,size:d}}function i(a,l,c){let h=l.array,d=l.updateRanges;if(n.bindBuffer(c,a),d.length===0)n.bufferSubData(c,0,h);else{d.sort((m,g)=>m.start-g.start);let u=0;for(let m=1;m<d.length;m++){let g=d[u],v=d[m];v.start<=g.start+g.count+1?g.count=Math.max(g.count,v.start+v.count-g.start):(++u,d[u]=v)}d.length=u+1;for(let m=0,g=d.length;m<g;m++){let v=d[m];n.bufferSubData(c,v.start*h.BYTES_PER_ELEMENT,h,v.start,v.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(a){return a.isInterleavedBufferAttribute&&(a=a.data),e.get(a)}function r(a){a.isInterleavedBufferAttribute&&(a=a.data);let l=e.get(a);l&&(n.deleteBuffer(l.buffer),e.delete(a))}function o(a,l){if(a.isInterleavedBufferAttribute&&(a=a.data),a.isGLBufferAttribute){let h=e.get(a);(!h||h.version<a.version)&&e.set(a,{buffer:a.buffer,type:a.type,bytesPerElement:a.elementSize,version:a.version});return}let c=e.get(a);if(c===void 0)e.set(a,t(a,l));else if(c.version<a.version){if(c.size!==a.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(c.buffer,a,l),c.version=a.version}}return{get:s,remove:r,update:o}}var Eb=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,Tb=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,Ab=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,Rb=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Cb=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,Ib=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,Pb=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,Lb=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,Nb=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,Db=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Ub=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,Ob=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,Fb=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,Bb=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,kb=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,zb=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,Gb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,Hb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,Vb=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,Wb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,Xb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,$b=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,qb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,Yb=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,Zb=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,Kb=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,Jb=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,jb=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,Qb=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,eS="gl_FragColor = linearToOutputTexel( gl_FragColor );",tS=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,nS=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,iS=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,sS=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,rS=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,oS=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,aS=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,lS=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,cS=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,hS=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,uS=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,dS=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,fS=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,pS=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,mS=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,gS=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,_S=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,yS=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,xS=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,vS=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,bS=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,SS=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,MS=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,wS=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,ES=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,TS=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,AS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,RS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,CS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,IS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,PS=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,LS=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,NS=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,DS=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,US=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,OS=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,FS=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,BS=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,kS=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,zS=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,GS=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,HS=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,VS=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,WS=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,XS=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,$S=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,qS=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,YS=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,ZS=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,KS=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,JS=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,jS=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,QS=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,eM=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,tM=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,nM=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,iM=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,sM=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,rM=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,oM=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,aM=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,lM=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,cM=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,hM=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,uM=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,dM=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,fM=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,pM=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,mM=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,gM=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,_M=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,yM=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,xM=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,vM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,bM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,SM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,MM=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,wM=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,EM=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,TM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,AM=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,RM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,CM=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,IM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,PM=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,LM=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,NM=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,DM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,UM=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,OM=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,FM=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,BM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,kM=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,zM=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,GM=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,HM=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,VM=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,WM=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,XM=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,$M=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,qM=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,YM=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,ZM=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,KM=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,JM=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,jM=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,QM=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,ew=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,tw=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,nw=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,iw=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,_t={alphahash_fragment:Eb,alphahash_pars_fragment:Tb,alphamap_fragment:Ab,alphamap_pars_fragment:Rb,alphatest_fragment:Cb,alphatest_pars_fragment:Ib,aomap_fragment:Pb,aomap_pars_fragment:Lb,batching_pars_vertex:Nb,batching_vertex:Db,begin_vertex:Ub,beginnormal_vertex:Ob,bsdfs:Fb,iridescence_fragment:Bb,bumpmap_pars_fragment:kb,clipping_planes_fragment:zb,clipping_planes_pars_fragment:Gb,clipping_planes_pars_vertex:Hb,clipping_planes_vertex:Vb,color_fragment:Wb,color_pars_fragment:Xb,color_pars_vertex:$b,color_vertex:qb,common:Yb,defaultnormal_vertex:Zb,displacementmap_pars_vertex:Kb,displacementmap_vertex:Jb,emissivemap_fragment:jb,emissivemap_pars_fragment:Qb,colorspace_fragment:eS,colorspace_pars_fragment:tS,envmap_fragment:nS,envmap_common_pars_fragment:iS,envmap_pars_fragment:sS,envmap_pars_vertex:rS,envmap_physical_pars_fragment:gS,envmap_vertex:oS,fog_vertex:aS,fog_pars_vertex:lS,fog_fragment:cS,fog_pars_fragment:hS,gradientmap_pars_fragment:uS,lightmap_pars_fragment:dS,lights_lambert_fragment:fS,lights_lambert_pars_fragment:pS,lights_pars_begin:mS,lights_toon_fragment:_S,lights_toon_pars_fragment:yS,lights_phong_fragment:xS,lights_phong_pars_fragment:vS,lights_physical_fragment:bS,lights_physical_pars_fragment:SS,lights_fragment_begin:MS,lights_fragment_maps:wS,lights_fragment_end:ES,lightprobes_pars_fragment:TS,logdepthbuf_fragment:AS,logdepthbuf_pars_fragment:RS,logdepthbuf_pars_vertex:CS,logdepthbuf_vertex:IS,map_fragment:PS,map_pars_fragment:LS,map_particle_fragment:NS,map_particle_pars_fragment:DS,metalnessmap_fragment:US,metalnessmap_pars_fragment:OS,morphinstance_vertex:FS,morphcolor_vertex:BS,morphnormal_vertex:kS,morphtarget_pars_vertex:zS,morphtarget_vertex:GS,normal_fragment_begin:HS,normal_fragment_maps:VS,normal_pars_fragment:WS,normal_pars_vertex:XS,normal_vertex:$S,normalmap_pars_fragment:qS,clearcoat_normal_fragment_begin:YS,clearcoat_normal_fragment_maps:ZS,clearcoat_pars_fragment:KS,iridescence_pars_fragment:JS,opaque_fragment:jS,packing:QS,premultiplied_alpha_fragment:eM,project_vertex:tM,dithering_fragment:nM,dithering_pars_fragment:iM,roughnessmap_fragment:sM,roughnessmap_pars_fragment:rM,shadowmap_pars_fragment:oM,shadowmap_pars_vertex:aM,shadowmap_vertex:lM,shadowmask_pars_fragment:cM,skinbase_vertex:hM,skinning_pars_vertex:uM,skinning_vertex:dM,skinnormal_vertex:fM,specularmap_fragment:pM,specularmap_pars_fragment:mM,tonemapping_fragment:gM,tonemapping_pars_fragment:_M,transmission_fragment:yM,transmission_pars_fragment:xM,uv_pars_fragment:vM,uv_pars_vertex:bM,uv_vertex:SM,worldpos_vertex:MM,background_vert:wM,background_frag:EM,backgroundCube_vert:TM,backgroundCube_frag:AM,cube_vert:RM,cube_frag:CM,depth_vert:IM,depth_frag:PM,distance_vert:LM,distance_frag:NM,equirect_vert:DM,equirect_frag:UM,linedashed_vert:OM,linedashed_frag:FM,meshbasic_vert:BM,meshbasic_frag:kM,meshlambert_vert:zM,meshlambert_frag:GM,meshmatcap_vert:HM,meshmatcap_frag:VM,meshnormal_vert:WM,meshnormal_frag:XM,meshphong_vert:$M,meshphong_frag:qM,meshphysical_vert:YM,meshphysical_frag:ZM,meshtoon_vert:KM,meshtoon_frag:JM,points_vert:jM,points_frag:QM,shadow_vert:ew,shadow_frag:tw,sprite_vert:nw,sprite_frag:iw},Ue={common:{diffuse:{value:new gt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new at},alphaMap:{value:null},alphaMapTransform:{value:new at},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new at}},envmap:{envMap:{value:null},envMapRotation:{value:new at},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new at}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new at}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new at},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new at},normalScale:{value:new ut(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new at},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new at}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new at}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new at}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new gt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new gt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new at},alphaTest:{value:0},uvTransform:{value:new at}},sprite:{diffuse:{value:new gt(16777215)},opacity:{value:1},center:{value:new ut(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new at},alphaMap:{value:null},alphaMapTransform:{value:new at},alphaTest:{value:0}}},os={basic:{uniforms:Vn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.fog]),vertexShader:_t.meshbasic_vert,fragmentShader:_t.meshbasic_frag},lambert:{uniforms:Vn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)},envMapIntensity:{value:1}}]),vertexShader:_t.meshlambert_vert,fragmentShader:_t.meshlambert_frag},phong:{uniforms:Vn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)},specular:{value:new gt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:_t.meshphong_vert,fragmentShader:_t.meshphong_frag},standard:{uniforms:Vn([Ue.common,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.roughnessmap,Ue.metalnessmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:_t.meshphysical_vert,fragmentShader:_t.meshphysical_frag},toon:{uniforms:Vn([Ue.common,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.gradientmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)}}]),vertexShader:_t.meshtoon_vert,fragmentShader:_t.meshtoon_frag},matcap:{uniforms:Vn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,{matcap:{value:null}}]),vertexShader:_t.meshmatcap_vert,fragmentShader:_t.meshmatcap_frag},points:{uniforms:Vn([Ue.points,Ue.fog]),vertexShader:_t.points_vert,fragmentShader:_t.points_frag},dashed:{uniforms:Vn([Ue.common,Ue.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:_t.linedashed_vert,fragmentShader:_t.linedashed_frag},depth:{uniforms:Vn([Ue.common,Ue.displacementmap]),vertexShader:_t.depth_vert,fragmentShader:_t.depth_frag},normal:{uniforms:Vn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,{opacity:{value:1}}]),vertexShader:_t.meshnormal_vert,fragmentShader:_t.meshnormal_frag},sprite:{uniforms:Vn([Ue.sprite,Ue.fog]),vertexShader:_t.sprite_vert,fragmentShader:_t.sprite_frag},background:{uniforms:{uvTransform:{value:new at},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:_t.background_vert,fragmentShader:_t.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new at}},vertexShader:_t.backgroundCube_vert,fragmentShader:_t.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:_t.cube_vert,fragmentShader:_t.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:_t.equirect_vert,fragmentShader:_t.equirect_frag},distance:{uniforms:Vn([Ue.common,Ue.displacementmap,{referencePosition:{value:new J},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:_t.distance_vert,fragmentShader:_t.distance_frag},shadow:{uniforms:Vn([Ue.lights,Ue.fog,{color:{value:new gt(0)},opacity:{value:1}}]),vertexShader:_t.shadow_vert,fragmentShader:_t.shadow_frag}};os.physical={uniforms:Vn([os.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new at},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new at},clearcoatNormalScale:{value:new ut(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new at},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new at},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new at},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new at},sheen:{value:0},sheenColor:{value:new gt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new at},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new at},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new at},transmissionSamplerSize:{value:new ut},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new at},attenuationDistance:{value:0},attenuationColor:{value:new gt(0)},specularColor:{value:new gt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new at},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new at},anisotropyVector:{value:new ut},anisotropyMap:{value:null},anisotropyMapTransform:{value:new at}}]),vertexShader:_t.meshphysical_vert,fragmentShader:_t.meshphysical_frag};var Gh={r:0,b:0,g:0},sw=new en,m_=new at;m_.set(-1,0,0,0,1,0,0,0,1);function rw(n,e,t,i,s,r){let o=new gt(0),a=s===!0?0:1,l,c,h=null,d=0,u=null;function m(x){let A=x.isScene===!0?x.background:null;if(A&&A.isTexture){let b=x.backgroundBlurriness>0;A=e.get(A,b)}return A}function g(x){let A=!1,b=m(x);b===null?f(o,a):b&&b.isColor&&(f(b,1),A=!0);let C=n.xr.getEnvironmentBlendMode();C==="additive"?t.buffers.color.setClear(0,0,0,1,r):C==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(n.autoClear||A)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function v(x,A){let b=m(A);b&&b.isCubeTexture?(c===void 0&&(c=new ts(new Lo(1,1,1),new ns({name:"BackgroundCubeMaterial",uniforms:Ur(os.backgroundCube.uniforms),vertexShader:os.backgroundCube.vertexShader,fragmentShader:os.backgroundCube.fragmentShader,side:jn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(C,w,_){this.matrixWorld.copyPosition(_.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(c)),c.material.uniforms.envMap.value=b,c.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(sw.makeRotationFromEuler(A.backgroundRotation)).transpose(),b.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(m_),c.material.toneMapped=Tt.getTransfer(b.colorSpace)!==Ft,(h!==b||d!==b.version||u!==n.toneMapping)&&(c.material.needsUpdate=!0,h=b,d=b.version,u=n.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):b&&b.isTexture&&(l===void 0&&(l=new ts(new Ba(2,2),new ns({name:"BackgroundMaterial",uniforms:Ur(os.background.uniforms),vertexShader:os.background.vertexShader,fragmentShader:os.background.fragmentShader,side:ar,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(l)),l.material.uniforms.t2D.value=b,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.toneMapped=Tt.getTransfer(b.colorSpace)!==Ft,b.matrixAutoUpdate===!0&&b.updateMatrix(),l.material.uniforms.uvTransform.value.copy(b.matrix),(h!==b||d!==b.version||u!==n.toneMapping)&&(l.material.needsUpdate=!0,h=b,d=b.version,u=n.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function f(x,A){x.getRGB(Gh,uf(n)),t.buffers.color.setClear(Gh.r,Gh.g,Gh.b,A,r)}function p(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return o},setClearColor:function(x,A=1){o.set(x),a=A,f(o,a)},getClearAlpha:function(){return a},setClearAlpha:function(x){a=x,f(o,a)},render:g,addToRenderList:v,dispose:p}}function ow(n,e){let t=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},s=u(null),r=s,o=!1;function a(R,z,F,P,B){let X=!1,D=d(R,P,F,z);r!==D&&(r=D,c(r.object)),X=m(R,P,F,B),X&&g(R,P,F,B),B!==null&&e.update(B,n.ELEMENT_ARRAY_BUFFER),(X||o)&&(o=!1,b(R,z,F,P),B!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(B).buffer))}function l(){return n.createVertexArray()}function c(R){return n.bindVertexArray(R)}function h(R){return n.deleteVertexArray(R)}function d(R,z,F,P){let B=P.wireframe===!0,X=i[z.id];X===void 0&&(X={},i[z.id]=X);let D=R.isInstancedMesh===!0?R.id:0,ne=X[D];ne===void 0&&(ne={},X[D]=ne);let q=ne[F.id];q===void 0&&(q={},ne[F.id]=q);let W=q[B];return W===void 0&&(W=u(l()),q[B]=W),W}function u(R){let z=[],F=[],P=[];for(let B=0;B<t;B++)z[B]=0,F[B]=0,P[B]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:z,enabledAttributes:F,attributeDivisors:P,object:R,attributes:{},index:null}}function m(R,z,F,P){let B=r.attributes,X=z.attributes,D=0,ne=F.getAttributes();for(let q in ne)if(ne[q].location>=0){let $=B[q],re=X[q];if(re===void 0&&(q==="instanceMatrix"&&R.instanceMatrix&&(re=R.instanceMatrix),q==="instanceColor"&&R.instanceColor&&(re=R.instanceColor)),$===void 0||$.attribute!==re||re&&$.data!==re.data)return!0;D++}return r.attributesNum!==D||r.index!==P}function g(R,z,F,P){let B={},X=z.attributes,D=0,ne=F.getAttributes();for(let q in ne)if(ne[q].location>=0){let $=X[q];$===void 0&&(q==="instanceMatrix"&&R.instanceMatrix&&($=R.instanceMatrix),q==="instanceColor"&&R.instanceColor&&($=R.instanceColor));let re={};re.attribute=$,$&&$.data&&(re.data=$.data),B[q]=re,D++}r.attributes=B,r.attributesNum=D,r.index=P}function v(){let R=r.newAttributes;for(let z=0,F=R.length;z<F;z++)R[z]=0}function f(R){p(R,0)}function p(R,z){let F=r.newAttributes,P=r.enabledAttributes,B=r.attributeDivisors;F[R]=1,P[R]===0&&(n.enableVertexAttribArray(R),P[R]=1),B[R]!==z&&(n.vertexAttribDivisor(R,z),B[R]=z)}function x(){let R=r.newAttributes,z=r.enabledAttributes;for(let F=0,P=z.length;F<P;F++)z[F]!==R[F]&&(n.disableVertexAttribArray(F),z[F]=0)}function A(R,z,F,P,B,X,D){D===!0?n.vertexAttribIPointer(R,z,F,B,X):n.vertexAttribPointer(R,z,F,P,B,X)}function b(R,z,F,P){v();let B=P.attributes,X=F.getAttributes(),D=z.defaultAttributeValues;for(let ne in X){let q=X[ne];if(q.location>=0){let W=B[ne];if(W===void 0&&(ne==="instanceMatrix"&&R.instanceMatrix&&(W=R.instanceMatrix),ne==="instanceColor"&&R.instanceColor&&(W=R.instanceColor)),W!==void 0){let $=W.normalized,re=W.itemSize,le=e.get(W);if(le===void 0)continue;let Q=le.buffer,me=le.type,fe=le.bytesPerElement,ve=me===n.INT||me===n.UNSIGNED_INT||W.gpuType===rh;if(W.isInterleavedBufferAttribute){let ye=W.data,Ve=ye.isInterleavedBuffer===!0?ye.stride:ye.itemSize,Je=W.offset;if(ye.isInstancedInterleavedBuffer||ye.isInstancedBufferAttribute){for(let Ne=0;Ne<q.locationSize;Ne++)p(q.location+Ne,ye.meshPerAttribute);R.isInstancedMesh!==!0&&P._maxInstanceCount===void 0&&(P._maxInstanceCount=ye.meshPerAttribute*ye.count)}else for(let Ne=0;Ne<q.locationSize;Ne++)f(q.location+Ne);n.bindBuffer(n.ARRAY_BUFFER,Q);for(let Ne=0;Ne<q.locationSize;Ne++)A(q.location+Ne,re/q.locationSize,me,$,Ve*fe,(Je+re/q.locationSize*Ne)*fe,ve)}else{if(W.isInstancedBufferAttribute){for(let ye=0;ye<q.locationSize;ye++)p(q.location+ye,W.meshPerAttribute);R.isInstancedMesh!==!0&&P._maxInstanceCount===void 0&&(P._maxInstanceCount=W.meshPerAttribute*W.count)}else for(let ye=0;ye<q.locationSize;ye++)f(q.location+ye);n.bindBuffer(n.ARRAY_BUFFER,Q);for(let ye=0;ye<q.locationSize;ye++)A(q.location+ye,re/q.locationSize,me,$,re*fe,re/q.locationSize*ye*fe,ve)}}else if(D!==void 0){let $=D[ne];if($!==void 0)switch($.length){case 2:n.vertexAttrib2fv(q.location,$);break;case 3:n.vertexAttrib3fv(q.location,$);break;case 4:n.vertexAttrib4fv(q.location,$);break;default:n.vertexAttrib1fv(q.location,$)}}}}x()}function C(){U();for(let R in i){let z=i[R];for(let F in z){let P=z[F];for(let B in P){let X=P[B];for(let D in X)h(X[D].object),delete X[D];delete P[B]}}delete i[R]}}function w(R){if(i[R.id]===void 0)return;let z=i[R.id];for(let F in z){let P=z[F];for(let B in P){let X=P[B];for(let D in X)h(X[D].object),delete X[D];delete P[B]}}delete i[R.id]}function _(R){for(let z in i){let F=i[z];for(let P in F){let B=F[P];if(B[R.id]===void 0)continue;let X=B[R.id];for(let D in X)h(X[D].object),delete X[D];delete B[R.id]}}}function M(R){for(let z in i){let F=i[z],P=R.isInstancedMesh===!0?R.id:0,B=F[P];if(B!==void 0){for(let X in B){let D=B[X];for(let ne in D)h(D[ne].object),delete D[ne];delete B[X]}delete F[P],Object.keys(F).length===0&&delete i[z]}}}function U(){L(),o=!0,r!==s&&(r=s,c(r.object))}function L(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:a,reset:U,resetDefaultState:L,dispose:C,releaseStatesOfGeometry:w,releaseStatesOfObject:M,releaseStatesOfProgram:_,initAttributes:v,enableAttribute:f,disableUnusedAttributes:x}}function aw(n,e,t){let i;function s(l){i=l}function r(l,c){n.drawArrays(i,l,c),t.update(c,i,1)}function o(l,c,h){h!==0&&(n.drawArraysInstanced(i,l,c,h),t.update(c,i,h))}function a(l,c,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,l,0,c,0,h);let u=0;for(let m=0;m<h;m++)u+=c[m];t.update(u,i,1)}this.setMode=s,this.render=r,this.renderInstances=o,this.renderMultiDraw=a}function lw(n,e,t,i){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){let _=e.get("EXT_texture_filter_anisotropic");s=n.getParameter(_.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function o(_){return!(_!==Gi&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function a(_){let M=_===zi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(_!==xi&&_!==ki&&!M&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function l(_){if(_==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";_="mediump"}return _==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp",h=l(c);h!==c&&(Ke("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);let d=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),u=t.logarithmicDepthBuffer===!0&&d===!1;t.reversedDepthBuffer===!0&&d===!1&&Ke("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&d===!0&&Ke("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let m=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),g=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),v=n.getParameter(n.MAX_TEXTURE_SIZE),f=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),p=n.getParameter(n.MAX_VERTEX_ATTRIBS),x=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),A=n.getParameter(n.MAX_VARYING_VECTORS),b=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),C=n.getParameter(n.MAX_SAMPLES),w=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:o,textureTypeReadable:a,precision:c,logarithmicDepthBuffer:u,reversedDepthBuffer:d,maxTextures:m,maxVertexTextures:g,maxTextureSize:v,maxCubemapSize:f,maxAttributes:p,maxVertexUniforms:x,maxVaryings:A,maxFragmentUniforms:b,maxSamples:C,samples:w}}function cw(n){let e=this,t=null,i=0,s=!1,r=!1,o=new pi,a=new at,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(d,u){let m=d.length!==0||u||i!==0||s;return s=u,i=d.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(d,u){t=h(d,u,0)},this.setState=function(d,u,m){let g=d.clippingPlanes,v=d.clipIntersection,f=d.clipShadows,p=n.get(d);if(!s||g===null||g.length===0||r&&!f)r?h(null):c();else{let x=r?0:i,A=x*4,b=p.clippingState||null;l.value=b,b=h(g,u,A,m);for(let C=0;C!==A;++C)b[C]=t[C];p.clippingState=b,this.numIntersection=v?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=i>0),e.numPlanes=i,e.numIntersection=0}function h(d,u,m,g){let v=d!==null?d.length:0,f=null;if(v!==0){if(f=l.value,g!==!0||f===null){let p=m+v*4,x=u.matrixWorldInverse;a.getNormalMatrix(x),(f===null||f.length<p)&&(f=new Float32Array(p));for(let A=0,b=m;A!==v;++A,b+=4)o.copy(d[A]).applyMatrix4(x,a),o.normal.toArray(f,b),f[b+3]=o.constant}l.value=f,l.needsUpdate=!0}return e.numPlanes=v,e.numIntersection=0,f}}var el=class extends _i{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let i={width:e,height:e,depth:1},s=[i,i,i,i,i,i];this.texture=new Ua(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new Lo(5,5,5),r=new ns({name:"CubemapFromEquirect",uniforms:Ur(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:jn,blending:Pr});r.uniforms.tEquirect.value=t;let o=new ts(s,r),a=t.minFilter;return t.minFilter===Ts&&(t.minFilter=Jn),new No(1,10,this).update(e,o),t.minFilter=a,o.geometry.dispose(),o.material.dispose(),this}clear(e,t=!0,i=!0,s=!0){let r=e.getRenderTarget();for(let o=0;o<6;o++)e.setRenderTarget(this,o),e.clear(t,i,s);e.setRenderTarget(r)}},q0=256,hw=3,uw=20,g_=256,__=16,dw=3,fw=new J,pw=new gt,Vh=class n{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new No(1,10,null),this._boxMesh=new ts(new Lo(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,i=.1,s=100,r={}){let{size:o=256,position:a=fw}=r,l=this._renderer;this._setSize(o);let c=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);let d=l.autoClear,u=l.autoClearColor,m=l.autoClearDepth,g=l.autoClearStencil,v=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,v===null&&(e.background=l.getClearColor(pw));let f=new No(i,s,h);return f.position.copy(a),f.update(l,e),l.autoClear=d,l.autoClearColor=u,l.autoClearDepth=m,l.autoClearStencil=g,e.background=v,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=K0(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Z0(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(q0,lf(e))}_fromTexture(e,t){e.mapping===Nr||e.mapping===Fo?this._setSize(e.image.length===0?q0:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);let i=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(i),i}_allocateTarget(){let e=this._cubeSize,t=Y0(e,!1,!1),i=Math.log2(e)-hw;for(let s=0;s<=i;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){let t=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==t||e&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=Y0(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,i){let s=this._boxMesh,r=this._cubeCamera;s.material=i,r.renderTarget=e,r.activeMipmapLevel=t;let o=e.width>>t;e.viewport.set(0,0,o,o),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Nr||e.mapping===Fo?(this._cubemapMaterial===null&&(this._cubemapMaterial=K0()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Z0()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=mw(),this._integrationMaterial=gw());let t=this._cubeSize,i=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;let r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/__);for(let o=0;o<=i;o++){let a=n.lodToRoughness(o,i);if(o>i-dw)r.roughness.value=a,this._renderCube(e,o,this._integrationMaterial);else{let l=a>0?Math.log2(t)+.5*Math.log2(6/(g_*Math.pow(a,4)))+.5:0;s.roughness.value=a,s.lodBias.value=l,this._renderCube(e,o,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=_w());let i=this._blurMaterial,s=i.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,i),s.envMap.value=e.texture,this._renderCube(r,0,i)}};function Y0(n,e,t){return new el(n,{minFilter:Ts,generateMipmaps:e,type:zi,colorSpace:wa,depthBuffer:t})}function tl(n,e,t){return new ns({name:n,uniforms:e,vertexShader:_t.cube_vert,fragmentShader:t,side:jn,blending:Pr,depthTest:!1,depthWrite:!1})}function mw(){return tl("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${g_}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function gw(){return tl("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:__}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function _w(){return tl("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${uw}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function Z0(){return tl("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function K0(){return tl("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function yw(n){let e=new WeakMap,t=new WeakMap,i=null;function s(u,m=!1){return u==null?null:m?o(u):r(u)}function r(u){if(u&&u.isTexture){let m=u.mapping;if(m===nh||m===ih)if(e.has(u)){let g=e.get(u).texture;return a(g,u.mapping)}else{let g=u.image;if(g&&g.height>0){let v=new el(g.height);return v.fromEquirectangularTexture(n,u),e.set(u,v),u.addEventListener("dispose",c),a(v.texture,u.mapping)}else return null}}return u}function o(u){if(u&&u.isTexture&&u.isPMREMTexture!==!0){let m=u.mapping,g=m===nh||m===ih,v=m===Nr||m===Fo;if(g||v){let f=t.get(u),p=f!==void 0?f.texture.pmremVersion:0;if(u.isRenderTargetTexture&&u.pmremVersion!==p)return i===null&&(i=new Vh(n)),f=g?i.fromEquirectangular(u,f):i.fromCubemap(u,f),f.texture.pmremVersion=u.pmremVersion,t.set(u,f),f.texture;if(f!==void 0)return f.texture;{let x=u.image;return g&&x&&x.height>0||v&&x&&l(x)?(i===null&&(i=new Vh(n)),f=g?i.fromEquirectangular(u):i.fromCubemap(u),f.texture.pmremVersion=u.pmremVersion,t.set(u,f),u.addEventListener("dispose",h),f.texture):null}}}return u}function a(u,m){return m===nh?u.mapping=Nr:m===ih&&(u.mapping=Fo),u}function l(u){let m=0,g=6;for(let v=0;v<g;v++)u[v]!==void 0&&m++;return m===g}function c(u){let m=u.target;m.removeEventListener("dispose",c);let g=e.get(m);g!==void 0&&(e.delete(m),g.dispose())}function h(u){let m=u.target;m.removeEventListener("dispose",h);let g=t.get(m);g!==void 0&&(t.delete(m),g.dispose())}function d(){e=new WeakMap,t=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:s,dispose:d}}function xw(n){let e={};function t(i){if(e[i]!==void 0)return e[i];let s=n.getExtension(i);return e[i]=s,s}return{has:function(i){return t(i)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(i){let s=t(i);return s===null&&va("WebGLRenderer: "+i+" extension not supported."),s}}}function vw(n,e,t,i){let s={},r=new WeakMap,o=new FinalizationRegistry(g=>delete s[g]);function a(g){l(g.target)}function l(g){g.index!==null&&e.remove(g.index);for(let f in g.attributes)e.remove(g.attributes[f]);g.removeEventListener("dispose",a),delete s[g.id],o.unregister(g);let v=r.get(g);v&&(e.remove(v),r.delete(g)),i.releaseStatesOfGeometry(g),g.isInstancedBufferGeometry===!0&&delete g._maxInstanceCount,t.memory.geometries--}function c(g,v){return s[v.id]!==void 0||(v.addEventListener("dispose",a),s[v.id]=new WeakRef(v),o.register(v,v.id,v),t.memory.geometries++),v}function h(g){let v=g.attributes;for(let f in v)e.update(v[f],n.ARRAY_BUFFER)}function d(g){let v=g.index,f=g.attributes.position,p=0;if(f===void 0)return;let x=v!==null?v.array.length:f.array.length/3-1,A=f.count>=65535?La:Pa,b=new A(Math.ceil(x/3)*6,1),C=b.array;if(v!==null){let _=v.array;p=v.version;for(let M=0,U=0;M<x;M+=3){let L=_[M+0],R=_[M+1],z=_[M+2];C[U++]=L,C[U++]=R,C[U++]=R,C[U++]=z,C[U++]=z,C[U++]=L}}else{p=f.version;for(let _=0,M=0;_<x;_+=3){let U=_+0,L=_+1,R=_+2;C[M++]=U,C[M++]=L,C[M++]=L,C[M++]=R,C[M++]=R,C[M++]=U}}b.version=p;let w=r.get(g);w&&e.remove(w),r.set(g,b)}function u(g){let v=r.get(g);if(v){let f=g.index;f!==null&&v.version<f.version&&d(g)}else d(g);return r.get(g)}function m(){for(let g in s){let v=s[g].deref();v!==void 0&&l(v)}}return{get:c,update:h,getWireframeAttribute:u,dispose:m}}function bw(n,e,t){let i;function s(d){i=d}let r,o;function a(d){r=d.type,o=d.bytesPerElement}function l(d,u){n.drawElements(i,u,r,d*o),t.update(u,i,1)}function c(d,u,m){m!==0&&(n.drawElementsInstanced(i,u,r,d*o,m),t.update(u,i,m))}function h(d,u,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,u,0,r,d,0,m);let v=0;for(let f=0;f<m;f++)v+=u[f];t.update(v,i,1)}this.setMode=s,this.setIndex=a,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function Sw(n){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function i(r,o,a){switch(t.calls++,o){case n.TRIANGLES:t.triangles+=a*(r/3);break;case n.LINES:t.lines+=a*(r/2);break;case n.LINE_STRIP:t.lines+=a*(r-1);break;case n.LINE_LOOP:t.lines+=a*r;break;case n.POINTS:t.points+=a*r;break;default:ot("WebGLInfo: Unknown draw mode:",o);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:i}}function Mw(n,e,t){let i=new WeakMap,s=new sn;function r(o,a,l){let c=o.morphTargetInfluences,h=a.morphAttributes.position||a.morphAttributes.normal||a.morphAttributes.color,d=h!==void 0?h.length:0,u=i.get(a);if(u===void 0||u.count!==d){let U=function(){_.dispose(),i.delete(a),a.removeEventListener("dispose",U)};u!==void 0&&u.texture.dispose();let m=a.morphAttributes.position!==void 0,g=a.morphAttributes.normal!==void 0,v=a.morphAttributes.color!==void 0,f=a.morphAttributes.position||[],p=a.morphAttributes.normal||[],x=a.morphAttributes.color||[],A=0;m===!0&&(A=1),g===!0&&(A=2),v===!0&&(A=3);let b=a.attributes.position.count*A,C=1;b>e.maxTextureSize&&(C=Math.ceil(b/e.maxTextureSize),b=e.maxTextureSize);let w=new Float32Array(b*C*4*d),_=new Ra(w,b,C,d);_.type=ki,_.needsUpdate=!0;let M=A*4;for(let L=0;L<d;L++){let R=f[L],z=p[L],F=x[L],P=b*C*4*L;for(let B=0;B<R.count;B++){let X=B*M;m===!0&&(s.fromBufferAttribute(R,B),w[P+X+0]=s.x,w[P+X+1]=s.y,w[P+X+2]=s.z,w[P+X+3]=0),g===!0&&(s.fromBufferAttribute(z,B),w[P+X+4]=s.x,w[P+X+5]=s.y,w[P+X+6]=s.z,w[P+X+7]=0),v===!0&&(s.fromBufferAttribute(F,B),w[P+X+8]=s.x,w[P+X+9]=s.y,w[P+X+10]=s.z,w[P+X+11]=F.itemSize===4?s.w:1)}}u={count:d,texture:_,size:new ut(b,C)},i.set(a,u),a.addEventListener("dispose",U)}if(o.isInstancedMesh===!0&&o.morphTexture!==null)l.getUniforms().setValue(n,"morphTexture",o.morphTexture,t);else{let m=0;for(let v=0;v<c.length;v++)m+=c[v];let g=a.morphTargetsRelative?1:1-m;l.getUniforms().setValue(n,"morphTargetBaseInfluence",g),l.getUniforms().setValue(n,"morphTargetInfluences",c)}l.getUniforms().setValue(n,"morphTargetsTexture",u.texture,t),l.getUniforms().setValue(n,"morphTargetsTextureSize",u.size)}return{update:r}}function ww(n,e,t,i,s){let r=new WeakMap;function o(c){let h=s.render.frame,d=c.geometry,u=e.get(c,d);if(r.get(u)!==h&&(e.update(u),r.set(u,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(t.update(c.instanceMatrix,n.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,n.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){let m=c.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return u}function a(){r=new WeakMap}function l(c){let h=c.target;h.removeEventListener("dispose",l),i.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:o,dispose:a}}var Ew={[kd]:"LINEAR_TONE_MAPPING",[zd]:"REINHARD_TONE_MAPPING",[Gd]:"CINEON_TONE_MAPPING",[Hd]:"ACES_FILMIC_TONE_MAPPING",[Wd]:"AGX_TONE_MAPPING",[Xd]:"NEUTRAL_TONE_MAPPING",[Vd]:"CUSTOM_TONE_MAPPING"};function Tw(n,e,t,i,s,r){let o=new _i(e,t,{type:n,depthBuffer:s,stencilBuffer:r,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),a=null,l=null,c=null,h=new ni;h.setAttribute("position",new Nn([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new Nn([0,2,0,0,2,0],2));let d=new zc({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),u=new ts(h,d),m=new Qc(-1,1,1,-1,0,1),g=null,v=null,f=!1,p,x=null,A=[],b=!1;this.setSize=function(C,w){o.setSize(C,w),a!==null&&a.setSize(C,w),l!==null&&l.setSize(C,w);for(let _=0;_<A.length;_++){let M=A[_];M.setSize&&M.setSize(C,w)}},this.setEffects=function(C){A=C,b=A.length>0&&A[0].isRenderPass===!0;let w=o.width,_=o.height;A.length>0&&a===null&&(a=new _i(w,_,{type:zi,depthBuffer:!1,stencilBuffer:!1}),l=new _i(w,_,{type:zi,depthBuffer:!1,stencilBuffer:!1}));let M=s===!0&&A.some(U=>U.needsDepthTexture===!0);M!==(o.depthTexture!==null)&&(M===!0&&c===null&&(c=new Es(w,_),r===!0&&(c.format=As,c.type=Dr)),o.dispose(),o.depthTexture=M?c:null,o.resolveDepthBuffer=M,o.storeMultisampledDepthBuffer=M);for(let U=0;U<A.length;U++){let L=A[U];L.setSize&&L.setSize(w,_),M&&L.needsDepthTexture===!0&&L.setDepthTexture&&L.setDepthTexture(c)}},this.begin=function(C,w){if(f||C.toneMapping===ss&&A.length===0)return!1;if(x=w,w!==null){let _=w.width,M=w.height;(o.width!==_||o.height!==M)&&this.setSize(_,M)}return b===!1&&C.setRenderTarget(o),p=C.toneMapping,C.toneMapping=ss,!0},this.hasRenderPass=function(){return b},this.end=function(C,w){C.toneMapping=p,f=!0;let _=o,M=a;for(let U=0;U<A.length;U++){let L=A[U];L.enabled!==!1&&(L.render(C,M,_,w),L.needsSwap!==!1&&(_=M,M=M===a?l:a))}if(g!==C.outputColorSpace||v!==C.toneMapping){g=C.outputColorSpace,v=C.toneMapping,d.defines={},Tt.getTransfer(g)===Ft&&(d.defines.SRGB_TRANSFER="");let U=Ew[v];U&&(d.defines[U]=""),d.needsUpdate=!0}d.uniforms.tDiffuse.value=_.texture,C.setRenderTarget(x),C.render(u,m),x=null,f=!1},this.isCompositing=function(){return f},this.dispose=function(){o.dispose(),a!==null&&a.dispose(),l!==null&&l.dispose(),h.dispose(),d.dispose()}}var y_=new ei,x_=new Es(1,1),v_=new Oa(1),b_=new Ra,S_=new Nc,M_=new Ua,J0=[],j0=[],Q0=new Float32Array(16),e_=new Float32Array(9),t_=new Float32Array(4);function Go(n,e,t){let i=n[0];if(i<=0||i>0)return n;let s=e*t,r=J0[s];if(r===void 0&&(r=new Float32Array(s),J0[s]=r),e!==0){i.toArray(r,0);for(let o=1,a=0;o!==e;++o)a+=t,n[o].toArray(r,a)}return r}function Mn(n,e){if(n.length!==e.length)return!1;for(let t=0,i=n.length;t<i;t++)if(n[t]!==e[t])return!1;return!0}function wn(n,e){for(let t=0,i=e.length;t<i;t++)n[t]=e[t]}function Xh(n,e){let t=j0[e];t===void 0&&(t=new Int32Array(e),j0[e]=t);for(let i=0;i!==e;++i)t[i]=n.allocateTextureUnit();return t}function Aw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function Rw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;n.uniform2fv(this.addr,e),wn(t,e)}}function Cw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(Mn(t,e))return;n.uniform3fv(this.addr,e),wn(t,e)}}function Iw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;n.uniform4fv(this.addr,e),wn(t,e)}}function Pw(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(Mn(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),wn(t,e)}else{if(Mn(t,i))return;t_.set(i),n.uniformMatrix2fv(this.addr,!1,t_),wn(t,i)}}function Lw(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(Mn(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),wn(t,e)}else{if(Mn(t,i))return;e_.set(i),n.uniformMatrix3fv(this.addr,!1,e_),wn(t,i)}}function Nw(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(Mn(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),wn(t,e)}else{if(Mn(t,i))return;Q0.set(i),n.uniformMatrix4fv(this.addr,!1,Q0),wn(t,i)}}function Dw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function Uw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;n.uniform2iv(this.addr,e),wn(t,e)}}function Ow(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Mn(t,e))return;n.uniform3iv(this.addr,e),wn(t,e)}}function Fw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;n.uniform4iv(this.addr,e),wn(t,e)}}function Bw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function kw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;n.uniform2uiv(this.addr,e),wn(t,e)}}function zw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Mn(t,e))return;n.uniform3uiv(this.addr,e),wn(t,e)}}function Gw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;n.uniform4uiv(this.addr,e),wn(t,e)}}function $h(n){return n.version===0&&(n.compareFunction=sf,n.needsUpdate=!0),n}function Hw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_2D_SHADOW?r=$h(x_):r=y_,t.setTexture2D(e||r,s)}function Vw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture3D(e||S_,s)}function Ww(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_CUBE_SHADOW?r=$h(v_):r=M_,t.setTextureCube(e||r,s)}function Xw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture2DArray(e||b_,s)}function $w(n){switch(n){case 5126:return Aw;case 35664:return Rw;case 35665:return Cw;case 35666:return Iw;case 35674:return Pw;case 35675:return Lw;case 35676:return Nw;case 5124:case 35670:return Dw;case 35667:case 35671:return Uw;case 35668:case 35672:return Ow;case 35669:case 35673:return Fw;case 5125:return Bw;case 36294:return kw;case 36295:return zw;case 36296:return Gw;case 35678:case 36198:case 36298:case 36306:case 35682:return Hw;case 35679:case 36299:case 36307:return Vw;case 35680:case 36300:case 36308:case 36293:return Ww;case 36289:case 36303:case 36311:case 36292:return Xw}}function qw(n,e){n.uniform1fv(this.addr,e)}function Yw(n,e){let t=Go(e,this.size,2);n.uniform2fv(this.addr,t)}function Zw(n,e){let t=Go(e,this.size,3);n.uniform3fv(this.addr,t)}function Kw(n,e){let t=Go(e,this.size,4);n.uniform4fv(this.addr,t)}function Jw(n,e){let t=Go(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function jw(n,e){let t=Go(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function Qw(n,e){let t=Go(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function eE(n,e){n.uniform1iv(this.addr,e)}function tE(n,e){n.uniform2iv(this.addr,e)}function nE(n,e){n.uniform3iv(this.addr,e)}function iE(n,e){n.uniform4iv(this.addr,e)}function sE(n,e){n.uniform1uiv(this.addr,e)}function rE(n,e){n.uniform2uiv(this.addr,e)}function oE(n,e){n.uniform3uiv(this.addr,e)}function aE(n,e){n.uniform4uiv(this.addr,e)}function lE(n,e,t){let i=this.cache,s=e.length,r=Xh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));let o;this.type===n.SAMPLER_2D_SHADOW?o=$h(x_):o=y_;for(let a=0;a!==s;++a)t.setTexture2D(e[a]||o,r[a])}function cE(n,e,t){let i=this.cache,s=e.length,r=Xh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));for(let o=0;o!==s;++o)t.setTexture3D(e[o]||S_,r[o])}function hE(n,e,t){let i=this.cache,s=e.length,r=Xh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));let o;this.type===n.SAMPLER_CUBE_SHADOW?o=$h(v_):o=M_;for(let a=0;a!==s;++a)t.setTextureCube(e[a]||o,r[a])}function uE(n,e,t){let i=this.cache,s=e.length,r=Xh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));for(let o=0;o!==s;++o)t.setTexture2DArray(e[o]||b_,r[o])}function dE(n){switch(n){case 5126:return qw;case 35664:return Yw;case 35665:return Zw;case 35666:return Kw;case 35674:return Jw;case 35675:return jw;case 35676:return Qw;case 5124:case 35670:return eE;case 35667:case 35671:return tE;case 35668:case 35672:return nE;case 35669:case 35673:return iE;case 5125:return sE;case 36294:return rE;case 36295:return oE;case 36296:return aE;case 35678:case 36198:case 36298:case 36306:case 35682:return lE;case 35679:case 36299:case 36307:return cE;case 35680:case 36300:case 36308:case 36293:return hE;case 36289:case 36303:case 36311:case 36292:return uE}}var Sf=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.setValue=$w(t.type)}},Mf=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=dE(t.type)}},wf=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,i){let s=this.seq;for(let r=0,o=s.length;r!==o;++r){let a=s[r];a.setValue(e,t[a.id],i)}}},vf=/(\w+)(\])?(\[|\.)?/g;function n_(n,e){n.seq.push(e),n.map[e.id]=e}function fE(n,e,t){let i=n.name,s=i.length;for(vf.lastIndex=0;;){let r=vf.exec(i),o=vf.lastIndex,a=r[1],l=r[2]==="]",c=r[3];if(l&&(a=a|0),c===void 0||c==="["&&o+2===s){n_(t,c===void 0?new Sf(a,n,e):new Mf(a,n,e));break}else{let d=t.map[a];d===void 0&&(d=new wf(a),n_(t,d)),t=d}}}var zo=class{constructor(e,t){this.seq=[],this.map={};let i=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let o=0;o<i;++o){let a=e.getActiveUniform(t,o),l=e.getUniformLocation(t,a.name);fE(a,l,this)}let s=[],r=[];for(let o of this.seq)o.type===e.SAMPLER_2D_SHADOW||o.type===e.SAMPLER_CUBE_SHADOW||o.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(o):r.push(o);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,i,s){let r=this.map[t];r!==void 0&&r.setValue(e,i,s)}setOptional(e,t,i){let s=t[i];s!==void 0&&this.setValue(e,i,s)}static upload(e,t,i,s){for(let r=0,o=t.length;r!==o;++r){let a=t[r],l=i[a.id];l.needsUpdate!==!1&&a.setValue(e,l.value,s)}}static seqWithValue(e,t){let i=[];for(let s=0,r=e.length;s!==r;++s){let o=e[s];o.id in t&&i.push(o)}return i}};function i_(n,e,t){let i=n.createShader(e);return n.shaderSource(i,t),n.compileShader(i),i}var pE=37297,mE=0;function gE(n,e){let t=n.split(`
`),i=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let o=s;o<r;o++){let a=o+1;i.push(`${a===e?">":" "} ${a}: ${t[o]}`)}return i.join(`
`)}var s_=new at;function _E(n){Tt._getMatrix(s_,Tt.workingColorSpace,n);let e=`mat3( ${s_.elements.map(t=>t.toFixed(4))} )`;switch(Tt.getTransfer(n)){case Ea:return[e,"LinearTransferOETF"];case Ft:return[e,"sRGBTransferOETF"];default:return Ke("WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function r_(n,e,t){let i=n.getShaderParameter(e,n.COMPILE_STATUS),r=(n.getShaderInfoLog(e)||"").trim();if(i&&r==="")return"";let o=/ERROR: 0:(\d+)/.exec(r);if(o){let a=parseInt(o[1]);return t.toUpperCase()+`

`+r+`

`+gE(n.getShaderSource(e),a)}else return r}function yE(n,e){let t=_E(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}var xE={[kd]:"Linear",[zd]:"Reinhard",[Gd]:"Cineon",[Hd]:"ACESFilmic",[Wd]:"AgX",[Xd]:"Neutral",[Vd]:"Custom"};function vE(n,e){let t=xE[e];return t===void 0?(Ke("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var Hh=new J;function bE(){Tt.getLuminanceCoefficients(Hh);let n=Hh.x.toFixed(4),e=Hh.y.toFixed(4),t=Hh.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function SE(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Qa).join(`
`)}function ME(n){let e=[];for(let t in n){let i=n[t];i!==!1&&e.push("#define "+t+" "+i)}return e.join(`
`)}function wE(n,e){let t={},i=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let s=0;s<i;s++){let r=n.getActiveAttrib(e,s),o=r.name,a=1;r.type===n.FLOAT_MAT2&&(a=2),r.type===n.FLOAT_MAT3&&(a=3),r.type===n.FLOAT_MAT4&&(a=4),t[o]={type:r.type,location:n.getAttribLocation(e,o),locationSize:a}}return t}function Qa(n){return n!==""}function o_(n,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function a_(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var EE=/^[ \t]*#include +<([\w\d./]+)>/gm;function Ef(n){return n.replace(EE,TE)}function TE(n,e){let t=_t[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return Ef(t)}var AE=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function l_(n){return n.replace(AE,RE)}function RE(n,e,t,i){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=i.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function c_(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}var CE={[Wa]:"SHADOWMAP_TYPE_PCF",[Uo]:"SHADOWMAP_TYPE_VSM"};function IE(n){return CE[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}var PE={[Fo]:"ENVMAP_MODE_REFRACTION"};function LE(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":PE[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}var NE={[Bd]:"ENVMAP_BLENDING_MULTIPLY",[E0]:"ENVMAP_BLENDING_MIX",[T0]:"ENVMAP_BLENDING_ADD"};function DE(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":NE[n.combine]||"ENVMAP_BLENDING_NONE"}function UE(n,e,t,i){let s=n.getContext(),r=t.defines,o=t.vertexShader,a=t.fragmentShader,l=IE(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=LE(t),d=DE(t),u=SE(t),m=ME(r),g=s.createProgram(),v,f,p=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(v=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Qa).join(`
`),v.length>0&&(v+=`
`),f=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Qa).join(`
`),f.length>0&&(f+=`
`)):(v=[c_(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Qa).join(`
`),f=[c_(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+h:"",t.envMap?"#define "+d:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==ss?"#define TONE_MAPPING":"",t.toneMapping!==ss?_t.tonemapping_pars_fragment:"",t.toneMapping!==ss?vE("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",_t.colorspace_pars_fragment,yE("linearToOutputTexel",t.outputColorSpace),bE(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Qa).join(`
`)),o=Ef(o),o=o_(o,t),o=a_(o,t),a=Ef(a),a=o_(a,t),a=a_(a,t),o=l_(o),a=l_(a),t.isRawShaderMaterial!==!0&&(p=`#version 300 es
`,v=[u,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+v,f=["#define varying in",t.glslVersion===rf?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===rf?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+f);let x=p+v+o,A=p+f+a,b=i_(s,s.VERTEX_SHADER,x),C=i_(s,s.FRAGMENT_SHADER,A);s.attachShader(g,b),s.attachShader(g,C),t.index0AttributeName!==void 0?s.bindAttribLocation(g,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(g,0,"position"),s.linkProgram(g);function w(L){if(n.debug.checkShaderErrors){let R=s.getProgramInfoLog(g)||"",z=s.getShaderInfoLog(b)||"",F=s.getShaderInfoLog(C)||"",P=R.trim(),B=z.trim(),X=F.trim(),D=!0,ne=!0;if(s.getProgramParameter(g,s.LINK_STATUS)===!1)if(D=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(s,g,b,C);else{let q=r_(s,b,"vertex"),W=r_(s,C,"fragment");ot("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(g,s.VALIDATE_STATUS)+`

Material Name: `+L.name+`
Material Type: `+L.type+`

Program Info Log: `+P+`
`+q+`
`+W)}else P!==""?Ke("WebGLProgram: Program Info Log:",P):(B===""||X==="")&&(ne=!1);ne&&(L.diagnostics={runnable:D,programLog:P,vertexShader:{log:B,prefix:v},fragmentShader:{log:X,prefix:f}})}s.deleteShader(b),s.deleteShader(C),_=new zo(s,g),M=wE(s,g)}let _;this.getUniforms=function(){return _===void 0&&w(this),_};let M;this.getAttributes=function(){return M===void 0&&w(this),M};let U=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return U===!1&&(U=s.getProgramParameter(g,pE)),U},this.destroy=function(){i.releaseStatesOfProgram(this),s.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=mE++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=b,this.fragmentShader=C,this}var OE=0,Tf=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,i){let s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(i)===!1&&(s.add(i),i.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let i of t)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,i=t.get(e);return i===void 0&&(i=new Set,t.set(e,i)),i}_getShaderStage(e){let t=this.shaderCache,i=t.get(e);return i===void 0&&(i=new Af(e),t.set(e,i)),i}},Af=class{constructor(e){this.id=OE++,this.code=e,this.usedTimes=0}};function FE(n){return n===lr||n===Ka||n===Ja}function BE(n,e,t,i,s,r){let o=new Ca,a=new Tf,l=new Set,c=[],h=new Map,d=i.logarithmicDepthBuffer,u={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(_){return l.add(_),_===0?"uv":`uv${_}`}function g(_,M,U,L,R,z){let F=L.fog,P=R.geometry,B=_.isMeshStandardMaterial||_.isMeshLambertMaterial||_.isMeshPhongMaterial?L.environment:null,X=_.isMeshStandardMaterial||_.isMeshLambertMaterial&&!_.envMap||_.isMeshPhongMaterial&&!_.envMap,D=e.get(_.envMap||B,X),ne=u[_.type],q=i.precision;_.precision!==null&&(q=i.getMaxPrecision(_.precision),q!==_.precision&&Ke("WebGLProgram.getParameters:",_.precision,"not supported, using",q,"instead."));let W=P.morphAttributes.position||P.morphAttributes.normal||P.morphAttributes.color,$=W!==void 0?W.length:0,re=0;P.morphAttributes.position!==void 0&&(re=1),P.morphAttributes.normal!==void 0&&(re=2),P.morphAttributes.color!==void 0&&(re=3);let le,Q,me,fe;if(ne){let Pe=os[ne];le=Pe.vertexShader,Q=Pe.fragmentShader}else{le=_.vertexShader,Q=_.fragmentShader;let Pe=a.getVertexShaderStage(_),ft=a.getFragmentShaderStage(_);a.update(_,Pe,ft),me=Pe.id,fe=ft.id}let ve=n.getRenderTarget(),ye=n.state.buffers.depth.getReversed(),Ve=R.isInstancedMesh===!0,Je=R.isBatchedMesh===!0,Ne=!!_.map,qe=!!_.matcap,Qe=!!D,pe=Qe&&D.isPMREMTexture===!0,Xe=!!_.aoMap,et=!!_.lightMap,Gt=!!_.bumpMap&&_.wireframe===!1,Rt=!!_.normalMap,cn=!!_.displacementMap,dt=!!_.emissiveMap,Pt=!!_.metalnessMap,At=!!_.roughnessMap,pt=_.anisotropy>0,k=_.clearcoat>0,be=_.diffuseRoughness>0,je=_.dispersion>0,ht=_.retroreflectivity>0,Ae=_.iridescence>0,Vt=_.sheen>0,We=_.transmission>0,Ze=pt&&!!_.anisotropyMap,I=k&&!!_.clearcoatMap,S=k&&!!_.clearcoatNormalMap,Y=k&&!!_.clearcoatRoughnessMap,de=be&&!!_.diffuseRoughnessMap,ce=Ae&&!!_.iridescenceMap,Me=Ae&&!!_.iridescenceThicknessMap,we=Vt&&!!_.sheenColorMap,ie=Vt&&!!_.sheenRoughnessMap,oe=!!_.specularMap,_e=!!_.specularColorMap,G=!!_.specularIntensityMap,ae=We&&!!_.transmissionMap,se=We&&!!_.thicknessMap,Re=!!_.gradientMap,Se=!!_.alphaMap,Te=_.alphaTest>0,$e=!!_.alphaHash,it=!!_.extensions,ue=ss;_.toneMapped&&(ve===null||ve.isXRRenderTarget===!0)&&(ue=n.toneMapping);let ze=pe?D.isCompressedCubeTexture?D.image[0].mipmaps:D.mipmaps:null,st={shaderID:ne,shaderType:_.type,shaderName:_.name,vertexShader:le,fragmentShader:Q,defines:_.defines,customVertexShaderID:me,customFragmentShaderID:fe,isRawShaderMaterial:_.isRawShaderMaterial===!0,glslVersion:_.glslVersion,precision:q,batching:Je,batchingColor:Je&&R._colorsTexture!==null,instancing:Ve,instancingColor:Ve&&R.instanceColor!==null,instancingMorph:Ve&&R.morphTexture!==null,outputColorSpace:ve===null?n.outputColorSpace:ve.isXRRenderTarget===!0?ve.texture.colorSpace:Tt.workingColorSpace,alphaToCoverage:!!_.alphaToCoverage,map:Ne,matcap:qe,envMap:Qe,envMapMode:Qe&&D.mapping,envMapPMREM:pe,envMapMaxLod:pe?ze.length-1:null,envMapSize:pe?ze[0].width:null,aoMap:Xe,lightMap:et,bumpMap:Gt,normalMap:Rt,displacementMap:cn,emissiveMap:dt,normalMapObjectSpace:Rt&&_.normalMapType===C0,normalMapTangentSpace:Rt&&_.normalMapType===ef,packedNormalMap:Rt&&_.normalMapType===ef&&FE(_.normalMap.format),metalnessMap:Pt,roughnessMap:At,anisotropy:pt,anisotropyMap:Ze,clearcoat:k,clearcoatMap:I,clearcoatNormalMap:S,clearcoatRoughnessMap:Y,diffuseRoughness:be,diffuseRoughnessMap:de,dispersion:je,retroreflection:ht,iridescence:Ae,iridescenceMap:ce,iridescenceThicknessMap:Me,sheen:Vt,sheenColorMap:we,sheenRoughnessMap:ie,specularMap:oe,specularColorMap:_e,specularIntensityMap:G,transmission:We,transmissionMap:ae,thicknessMap:se,gradientMap:Re,opaque:_.transparent===!1&&_.blending===Oo&&_.alphaToCoverage===!1,alphaMap:Se,alphaTest:Te,alphaHash:$e,combine:_.combine,mapUv:Ne&&m(_.map.channel),aoMapUv:Xe&&m(_.aoMap.channel),lightMapUv:et&&m(_.lightMap.channel),bumpMapUv:Gt&&m(_.bumpMap.channel),normalMapUv:Rt&&m(_.normalMap.channel),displacementMapUv:cn&&m(_.displacementMap.channel),emissiveMapUv:dt&&m(_.emissiveMap.channel),metalnessMapUv:Pt&&m(_.metalnessMap.channel),roughnessMapUv:At&&m(_.roughnessMap.channel),anisotropyMapUv:Ze&&m(_.anisotropyMap.channel),clearcoatMapUv:I&&m(_.clearcoatMap.channel),clearcoatNormalMapUv:S&&m(_.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:Y&&m(_.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:de&&m(_.diffuseRoughnessMap.channel),iridescenceMapUv:ce&&m(_.iridescenceMap.channel),iridescenceThicknessMapUv:Me&&m(_.iridescenceThicknessMap.channel),sheenColorMapUv:we&&m(_.sheenColorMap.channel),sheenRoughnessMapUv:ie&&m(_.sheenRoughnessMap.channel),specularMapUv:oe&&m(_.specularMap.channel),specularColorMapUv:_e&&m(_.specularColorMap.channel),specularIntensityMapUv:G&&m(_.specularIntensityMap.channel),transmissionMapUv:ae&&m(_.transmissionMap.channel),thicknessMapUv:se&&m(_.thicknessMap.channel),alphaMapUv:Se&&m(_.alphaMap.channel),vertexTangents:!!P.attributes.tangent&&(Rt||pt),vertexNormals:!!P.attributes.normal,vertexColors:_.vertexColors,vertexAlphas:_.vertexColors===!0&&!!P.attributes.color&&P.attributes.color.itemSize===4,pointsUvs:R.isPoints===!0&&!!P.attributes.uv&&(Ne||Se),fog:!!F,useFog:_.fog===!0,fogExp2:!!F&&F.isFogExp2,flatShading:_.wireframe===!1&&(_.flatShading===!0||P.attributes.normal===void 0&&Rt===!1&&(_.isMeshLambertMaterial||_.isMeshPhongMaterial||_.isMeshStandardMaterial||_.isMeshPhysicalMaterial)),sizeAttenuation:_.sizeAttenuation===!0,logarithmicDepthBuffer:d,reversedDepthBuffer:ye,skinning:R.isSkinnedMesh===!0,hasPositionAttribute:P.attributes.position!==void 0,morphTargets:P.morphAttributes.position!==void 0,morphNormals:P.morphAttributes.normal!==void 0,morphColors:P.morphAttributes.color!==void 0,morphTargetsCount:$,morphTextureStride:re,numSunLights:M.sun.length,numDirLights:M.directional.length,numPointLights:M.point.length,numSpotLights:M.spot.length,numSpotLightMaps:M.spotLightMap.length,numRectAreaLights:M.rectArea.length,numHemiLights:M.hemi.length,numSunLightShadows:M.sunShadowMap.length,numDirLightShadows:M.directionalShadowMap.length,numPointLightShadows:M.pointShadowMap.length,numSpotLightShadows:M.spotShadowMap.length,numSpotLightShadowsWithMaps:M.numSpotLightShadowsWithMaps,numLightProbes:M.numLightProbes,numLightProbeGrids:z.filter(Pe=>Pe.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:_.dithering,shadowMapEnabled:n.shadowMap.enabled&&U.length>0,shadowMapType:n.shadowMap.type,toneMapping:ue,decodeVideoTexture:Ne&&_.map.isVideoTexture===!0&&Tt.getTransfer(_.map.colorSpace)===Ft,decodeVideoTextureEmissive:dt&&_.emissiveMap.isVideoTexture===!0&&Tt.getTransfer(_.emissiveMap.colorSpace)===Ft,premultipliedAlpha:_.premultipliedAlpha,doubleSided:_.side===is,flipSided:_.side===jn,useDepthPacking:_.depthPacking>=0,depthPacking:_.depthPacking||0,index0AttributeName:_.index0AttributeName,extensionClipCullDistance:it&&_.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(it&&_.extensions.multiDraw===!0||Je)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:_.customProgramCacheKey()};return st.vertexUv1s=l.has(1),st.vertexUv2s=l.has(2),st.vertexUv3s=l.has(3),l.clear(),st}function v(_){let M=[];if(_.shaderID?M.push(_.shaderID):(M.push(_.customVertexShaderID),M.push(_.customFragmentShaderID)),_.defines!==void 0)for(let U in _.defines)M.push(U),M.push(_.defines[U]);return _.isRawShaderMaterial===!1&&(f(M,_),p(M,_),M.push(n.outputColorSpace)),M.push(_.customProgramCacheKey),M.join()}function f(_,M){_.push(M.precision),_.push(M.outputColorSpace),_.push(M.envMapMode),_.push(M.envMapPMREM),_.push(M.envMapMaxLod),_.push(M.envMapSize),_.push(M.mapUv),_.push(M.alphaMapUv),_.push(M.lightMapUv),_.push(M.aoMapUv),_.push(M.bumpMapUv),_.push(M.normalMapUv),_.push(M.displacementMapUv),_.push(M.emissiveMapUv),_.push(M.metalnessMapUv),_.push(M.roughnessMapUv),_.push(M.anisotropyMapUv),_.push(M.clearcoatMapUv),_.push(M.clearcoatNormalMapUv),_.push(M.clearcoatRoughnessMapUv),_.push(M.diffuseRoughnessMapUv),_.push(M.iridescenceMapUv),_.push(M.iridescenceThicknessMapUv),_.push(M.sheenColorMapUv),_.push(M.sheenRoughnessMapUv),_.push(M.specularMapUv),_.push(M.specularColorMapUv),_.push(M.specularIntensityMapUv),_.push(M.transmissionMapUv),_.push(M.thicknessMapUv),_.push(M.combine),_.push(M.fogExp2),_.push(M.sizeAttenuation),_.push(M.morphTargetsCount),_.push(M.numSunLights),_.push(M.numDirLights),_.push(M.numPointLights),_.push(M.numSpotLights),_.push(M.numSpotLightMaps),_.push(M.numHemiLights),_.push(M.numRectAreaLights),_.push(M.numSunLightShadows),_.push(M.numDirLightShadows),_.push(M.numPointLightShadows),_.push(M.numSpotLightShadows),_.push(M.numSpotLightShadowsWithMaps),_.push(M.numLightProbes),_.push(M.numLightProbeGrids),_.push(M.shadowMapType),_.push(M.toneMapping),_.push(M.numClippingPlanes),_.push(M.numClipIntersection),_.push(M.depthPacking)}function p(_,M){o.disableAll(),M.instancing&&o.enable(0),M.instancingColor&&o.enable(1),M.instancingMorph&&o.enable(2),M.matcap&&o.enable(3),M.envMap&&o.enable(4),M.normalMapObjectSpace&&o.enable(5),M.normalMapTangentSpace&&o.enable(6),M.clearcoat&&o.enable(7),M.iridescence&&o.enable(8),M.alphaTest&&o.enable(9),M.vertexColors&&o.enable(10),M.vertexAlphas&&o.enable(11),M.vertexUv1s&&o.enable(12),M.vertexUv2s&&o.enable(13),M.vertexUv3s&&o.enable(14),M.vertexTangents&&o.enable(15),M.anisotropy&&o.enable(16),M.alphaHash&&o.enable(17),M.batching&&o.enable(18),M.dispersion&&o.enable(19),M.retroreflection&&o.enable(24),M.diffuseRoughness&&o.enable(25),M.batchingColor&&o.enable(20),M.gradientMap&&o.enable(21),M.packedNormalMap&&o.enable(22),M.vertexNormals&&o.enable(23),_.push(o.mask),o.disableAll(),M.fog&&o.enable(0),M.useFog&&o.enable(1),M.flatShading&&o.enable(2),M.logarithmicDepthBuffer&&o.enable(3),M.reversedDepthBuffer&&o.enable(4),M.skinning&&o.enable(5),M.morphTargets&&o.enable(6),M.morphNormals&&o.enable(7),M.morphColors&&o.enable(8),M.premultipliedAlpha&&o.enable(9),M.shadowMapEnabled&&o.enable(10),M.doubleSided&&o.enable(11),M.flipSided&&o.enable(12),M.useDepthPacking&&o.enable(13),M.dithering&&o.enable(14),M.transmission&&o.enable(15),M.sheen&&o.enable(16),M.opaque&&o.enable(17),M.pointsUvs&&o.enable(18),M.decodeVideoTexture&&o.enable(19),M.decodeVideoTextureEmissive&&o.enable(20),M.alphaToCoverage&&o.enable(21),M.numLightProbeGrids>0&&o.enable(22),M.hasPositionAttribute&&o.enable(23),_.push(o.mask)}function x(_){let M=u[_.type],U;if(M){let L=os[M];U=W0.clone(L.uniforms)}else U=_.uniforms;return U}function A(_,M){let U=h.get(M);return U!==void 0?++U.usedTimes:(U=new UE(n,M,_,s),c.push(U),h.set(M,U)),U}function b(_){if(--_.usedTimes===0){let M=c.indexOf(_);c[M]=c[c.length-1],c.pop(),h.delete(_.cacheKey),_.destroy()}}function C(_){a.remove(_)}function w(){a.dispose()}return{getParameters:g,getProgramCacheKey:v,getUniforms:x,acquireProgram:A,releaseProgram:b,releaseShaderCache:C,programs:c,dispose:w}}function kE(){let n=new WeakMap;function e(o){return n.has(o)}function t(o){let a=n.get(o);return a===void 0&&(a={},n.set(o,a)),a}function i(o){n.delete(o)}function s(o,a,l){n.get(o)[a]=l}function r(){n=new WeakMap}return{has:e,get:t,remove:i,update:s,dispose:r}}function zE(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.materialVariant!==e.materialVariant?n.materialVariant-e.materialVariant:n.z!==e.z?n.z-e.z:n.id-e.id}function h_(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function u_(){let n=[],e=0,t=[],i=[],s=[];function r(){e=0,t.length=0,i.length=0,s.length=0}function o(u){let m=0;return u.isInstancedMesh&&(m+=2),u.isSkinnedMesh&&(m+=1),m}function a(u,m,g,v,f,p){let x=n[e];return x===void 0?(x={id:u.id,object:u,geometry:m,material:g,materialVariant:o(u),groupOrder:v,renderOrder:u.renderOrder,z:f,group:p},n[e]=x):(x.id=u.id,x.object=u,x.geometry=m,x.material=g,x.materialVariant=o(u),x.groupOrder=v,x.renderOrder=u.renderOrder,x.z=f,x.group=p),e++,x}function l(u,m,g,v,f,p,x){x.reversedDepth===!0&&(f=-f);let A=a(u,m,g,v,f,p);g.transmission>0?i.push(A):g.transparent===!0?s.push(A):t.push(A)}function c(u,m,g,v,f,p){let x=a(u,m,g,v,f,p);g.transmission>0?i.unshift(x):g.transparent===!0?s.unshift(x):t.unshift(x)}function h(u,m){t.length>1&&t.sort(u||zE),i.length>1&&i.sort(m||h_),s.length>1&&s.sort(m||h_)}function d(){for(let u=e,m=n.length;u<m;u++){let g=n[u];if(g.id===null)break;g.id=null,g.object=null,g.geometry=null,g.material=null,g.group=null}}return{opaque:t,transmissive:i,transparent:s,init:r,push:l,unshift:c,finish:d,sort:h}}function GE(){let n=new WeakMap;function e(i,s){let r=n.get(i),o;return r===void 0?(o=new u_,n.set(i,[o])):s>=r.length?(o=new u_,r.push(o)):o=r[s],o}function t(){n=new WeakMap}return{get:e,dispose:t}}function HE(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new J,color:new gt};break;case"SpotLight":t={position:new J,direction:new J,color:new gt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new J,color:new gt,distance:0,decay:0};break;case"HemisphereLight":t={direction:new J,skyColor:new gt,groundColor:new gt};break;case"RectAreaLight":t={color:new gt,position:new J,halfWidth:new J,halfHeight:new J};break}return n[e.id]=t,t}}}function VE(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ut};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ut};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ut,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}var WE=0;function XE(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function $E(n){let e=new HE,t=VE(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)i.probe.push(new J);let s=new J,r=new en,o=new en;function a(c){let h=0,d=0,u=0;for(let z=0;z<9;z++)i.probe[z].set(0,0,0);let m=0,g=0,v=0,f=0,p=0,x=0,A=0,b=0,C=0,w=0,_=0,M=0,U=0,L=0;c.sort(XE);for(let z=0,F=c.length;z<F;z++){let P=c[z],B=P.color,X=P.intensity,D=P.distance,ne=null;if(P.shadow&&P.shadow.map&&(P.shadow.map.texture.format===lr?ne=P.shadow.map.texture:ne=P.shadow.map.depthTexture||P.shadow.map.texture),P.isAmbientLight)h+=B.r*X,d+=B.g*X,u+=B.b*X;else if(P.isLightProbe){for(let q=0;q<9;q++)i.probe[q].addScaledVector(P.sh.coefficients[q],X);L++}else if(P.isSunLight){let q=e.get(P);if(q.color.copy(P.color).multiplyScalar(P.intensity),P.castShadow){let W=P.shadow,$=t.get(P);$.shadowIntensity=W.intensity,$.shadowBias=W.bias,$.shadowNormalBias=W.normalBias,$.shadowRadius=W.radius,$.shadowMapSize.copy(W.mapSize).multiply(W.getFrameExtents()),i.sunShadow[g]=$,i.sunShadowMap[g]=ne;let re=W.getViewportCount();for(let le=0;le<re;le++)i.sunShadowMatrix[v+le]=W.getMatrix(le),i.sunShadowCascade[v+le]=W._cascadeData[le];v+=re,g++}i.sun[m]=q,m++}else if(P.isDirectionalLight){let q=e.get(P);if(q.color.copy(P.color).multiplyScalar(P.intensity),P.castShadow){let W=P.shadow,$=t.get(P);$.shadowIntensity=W.intensity,$.shadowBias=W.bias,$.shadowNormalBias=W.normalBias,$.shadowRadius=W.radius,$.shadowMapSize=W.mapSize,i.directionalShadow[f]=$,i.directionalShadowMap[f]=ne,i.directionalShadowMatrix[f]=P.shadow.matrix,C++}i.directional[f]=q,f++}else if(P.isSpotLight){let q=e.get(P);q.position.setFromMatrixPosition(P.matrixWorld),q.color.copy(B).multiplyScalar(X),q.distance=D,q.coneCos=Math.cos(P.angle),q.penumbraCos=Math.cos(P.angle*(1-P.penumbra)),q.decay=P.decay,i.spot[x]=q;let W=P.shadow;if(P.map&&(i.spotLightMap[M]=P.map,M++,W.updateMatrices(P),P.castShadow&&U++),i.spotLightMatrix[x]=W.matrix,P.castShadow){let $=t.get(P);$.shadowIntensity=W.intensity,$.shadowBias=W.bias,$.shadowNormalBias=W.normalBias,$.shadowRadius=W.radius,$.shadowMapSize=W.mapSize,i.spotShadow[x]=$,i.spotShadowMap[x]=ne,_++}x++}else if(P.isRectAreaLight){let q=e.get(P);q.color.copy(B).multiplyScalar(X),q.halfWidth.set(P.width*.5,0,0),q.halfHeight.set(0,P.height*.5,0),i.rectArea[A]=q,A++}else if(P.isPointLight){let q=e.get(P);if(q.color.copy(P.color).multiplyScalar(P.intensity),q.distance=P.distance,q.decay=P.decay,P.castShadow){let W=P.shadow,$=t.get(P);$.shadowIntensity=W.intensity,$.shadowBias=W.bias,$.shadowNormalBias=W.normalBias,$.shadowRadius=W.radius,$.shadowMapSize=W.mapSize,$.shadowCameraNear=W.camera.near,$.shadowCameraFar=W.camera.far,i.pointShadow[p]=$,i.pointShadowMap[p]=ne,i.pointShadowMatrix[p]=P.shadow.matrix,w++}i.point[p]=q,p++}else if(P.isHemisphereLight){let q=e.get(P);q.skyColor.copy(P.color).multiplyScalar(X),q.groundColor.copy(P.groundColor).multiplyScalar(X),i.hemi[b]=q,b++}}A>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=Ue.LTC_FLOAT_1,i.rectAreaLTC2=Ue.LTC_FLOAT_2):(i.rectAreaLTC1=Ue.LTC_HALF_1,i.rectAreaLTC2=Ue.LTC_HALF_2)),i.ambient[0]=h,i.ambient[1]=d,i.ambient[2]=u;let R=i.hash;(R.sunLength!==m||R.directionalLength!==f||R.pointLength!==p||R.spotLength!==x||R.rectAreaLength!==A||R.hemiLength!==b||R.numSunShadows!==g||R.numDirectionalShadows!==C||R.numPointShadows!==w||R.numSpotShadows!==_||R.numSpotMaps!==M||R.numLightProbes!==L)&&(i.sun.length=m,i.directional.length=f,i.spot.length=x,i.rectArea.length=A,i.point.length=p,i.hemi.length=b,i.sunShadow.length=g,i.sunShadowMap.length=g,i.sunShadowMatrix.length=v,i.sunShadowCascade.length=v,i.directionalShadow.length=C,i.directionalShadowMap.length=C,i.directionalShadowMatrix.length=C,i.pointShadow.length=w,i.pointShadowMap.length=w,i.pointShadowMatrix.length=w,i.spotShadow.length=_,i.spotShadowMap.length=_,i.spotLightMatrix.length=_+M-U,i.spotLightMap.length=M,i.numSpotLightShadowsWithMaps=U,i.numLightProbes=L,R.sunLength=m,R.directionalLength=f,R.pointLength=p,R.spotLength=x,R.rectAreaLength=A,R.hemiLength=b,R.numSunShadows=g,R.numDirectionalShadows=C,R.numPointShadows=w,R.numSpotShadows=_,R.numSpotMaps=M,R.numLightProbes=L,i.version=WE++)}function l(c,h){let d=0,u=0,m=0,g=0,v=0,f=0,p=h.matrixWorldInverse;for(let x=0,A=c.length;x<A;x++){let b=c[x];if(b.isSunLight){let C=i.sun[d];C.direction.setFromMatrixPosition(b.matrixWorld),C.direction.transformDirection(p),d++}else if(b.isDirectionalLight){let C=i.directional[u];C.direction.setFromMatrixPosition(b.matrixWorld),s.setFromMatrixPosition(b.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(p),u++}else if(b.isSpotLight){let C=i.spot[g];C.position.setFromMatrixPosition(b.matrixWorld),C.position.applyMatrix4(p),C.direction.setFromMatrixPosition(b.matrixWorld),s.setFromMatrixPosition(b.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(p),g++}else if(b.isRectAreaLight){let C=i.rectArea[v];C.position.setFromMatrixPosition(b.matrixWorld),C.position.applyMatrix4(p),o.identity(),r.copy(b.matrixWorld),r.premultiply(p),o.extractRotation(r),C.halfWidth.set(b.width*.5,0,0),C.halfHeight.set(0,b.height*.5,0),C.halfWidth.applyMatrix4(o),C.halfHeight.applyMatrix4(o),v++}else if(b.isPointLight){let C=i.point[m];C.position.setFromMatrixPosition(b.matrixWorld),C.position.applyMatrix4(p),m++}else if(b.isHemisphereLight){let C=i.hemi[f];C.direction.setFromMatrixPosition(b.matrixWorld),C.direction.transformDirection(p),f++}}}return{setup:a,setupView:l,state:i}}function d_(n){let e=new $E(n),t=[],i=[],s=[];function r(d){h.camera=d,t.length=0,i.length=0,s.length=0}function o(d){d.isLightProbeGrid?s.push(d):t.push(d)}function a(d){i.push(d)}function l(){e.setup(t),s.sort((d,u)=>d.priority-u.priority||d.id-u.id)}function c(d){e.setupView(t,d)}let h={lightsArray:t,shadowsArray:i,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:o,pushShadow:a}}function qE(n){let e=new WeakMap;function t(s,r=0){let o=e.get(s),a;return o===void 0?(a=new d_(n),e.set(s,[a])):r>=o.length?(a=new d_(n),o.push(a)):a=o[r],a}function i(){e=new WeakMap}return{get:t,dispose:i}}var YE=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,ZE=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,KE=[new J(1,0,0),new J(-1,0,0),new J(0,1,0),new J(0,-1,0),new J(0,0,1),new J(0,0,-1)],JE=[new J(0,-1,0),new J(0,-1,0),new J(0,0,1),new J(0,0,-1),new J(0,-1,0),new J(0,-1,0)],f_=new en,ja=new J,bf=new J;function jE(n,e,t){let i=new Ir,s=new ut,r=new ut,o=new sn,a=new Gc,l=new Hc,c={},h=t.maxTextureSize,d={[ar]:jn,[jn]:ar,[is]:is},u=new ns({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new ut},radius:{value:4}},vertexShader:YE,fragmentShader:ZE}),m=u.clone();m.defines.HORIZONTAL_PASS=1;let g=new ni;g.setAttribute("position",new mi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let v=new ts(g,u),f=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Wa;let p=this.type;this.render=function(w,_,M){if(f.enabled===!1||f.autoUpdate===!1&&f.needsUpdate===!1||w.length===0)return;this.type===o0&&(Ke("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Wa);let U=n.getRenderTarget(),L=n.getActiveCubeFace(),R=n.getActiveMipmapLevel(),z=n.state;z.setBlending(Pr),z.buffers.depth.getReversed()===!0?z.buffers.color.setClear(0,0,0,0):z.buffers.color.setClear(1,1,1,1),z.buffers.depth.setTest(!0),z.setScissorTest(!1);let F=p!==this.type;F&&_.traverse(function(P){P.material&&(Array.isArray(P.material)?P.material.forEach(B=>B.needsUpdate=!0):P.material.needsUpdate=!0)});for(let P=0,B=w.length;P<B;P++){let X=w[P],D=X.shadow;if(D===void 0){Ke("WebGLShadowMap:",X,"has no shadow.");continue}if(D.autoUpdate===!1&&D.needsUpdate===!1)continue;s.copy(D.mapSize);let ne=D.getFrameExtents();s.multiply(ne),r.copy(D.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/ne.x),s.x=r.x*ne.x,D.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/ne.y),s.y=r.y*ne.y,D.mapSize.y=r.y));let q=n.state.buffers.depth.getReversed();if(D.camera._reversedDepth=q,D.map===null||F===!0){if(D.map!==null&&(D.map.depthTexture!==null&&(D.map.depthTexture.dispose(),D.map.depthTexture=null),D.map.dispose()),this.type===Uo){if(X.isPointLight){Ke("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}D.map=new _i(s.x,s.y,{format:lr,type:zi,minFilter:Jn,magFilter:Jn,generateMipmaps:!1}),D.map.texture.name=X.name+".shadowMap",D.map.depthTexture=new Es(s.x,s.y,ki),D.map.depthTexture.name=X.name+".shadowMapDepth",D.map.depthTexture.format=Ms,D.map.depthTexture.compareFunction=null,D.map.depthTexture.minFilter=Dn,D.map.depthTexture.magFilter=Dn}else X.isPointLight?(D.map=new el(s.x),D.map.depthTexture=new Oa(s.x,Bi)):(D.map=new _i(s.x,s.y),D.map.depthTexture=new Es(s.x,s.y,Bi)),D.map.depthTexture.name=X.name+".shadowMap",D.map.depthTexture.format=Ms,this.type===Wa?(D.map.depthTexture.compareFunction=q?nf:tf,D.map.depthTexture.minFilter=Jn,D.map.depthTexture.magFilter=Jn):(D.map.depthTexture.compareFunction=null,D.map.depthTexture.minFilter=Dn,D.map.depthTexture.magFilter=Dn);D.camera.updateProjectionMatrix()}D.map.isWebGLCubeRenderTarget!==!0&&(D.map.width!==s.x||D.map.height!==s.y)&&D.map.setSize(s.x,s.y);let W=D.map.isWebGLCubeRenderTarget?6:D.getViewportCount();X.isPointLight!==!0&&D.updateMatrices(X,M);let $=(D.camera.layers.mask&4294967294)!==0?D.camera.layers:M.layers;for(let re=0;re<W;re++){let le=D.getCamera(re);if(X.isPointLight){let Q=D.camera,me=D.matrix,fe=X.distance||Q.far;fe!==Q.far&&(Q.far=fe,Q.updateProjectionMatrix()),ja.setFromMatrixPosition(X.matrixWorld),Q.position.copy(ja),bf.copy(Q.position),bf.add(KE[re]),Q.up.copy(JE[re]),Q.lookAt(bf),Q.updateMatrixWorld(),me.makeTranslation(-ja.x,-ja.y,-ja.z),f_.multiplyMatrices(Q.projectionMatrix,Q.matrixWorldInverse),D._frustum.setFromProjectionMatrix(f_,Q.coordinateSystem,Q.reversedDepth)}if(D.map.isWebGLCubeRenderTarget)n.setRenderTarget(D.map,re),n.clear();else{re===0&&(n.setRenderTarget(D.map),n.clear());let Q=D.getViewport(re);o.set(r.x*Q.x,r.y*Q.y,r.x*Q.z,r.y*Q.w),z.viewport(o)}i=D.getFrustum(re),b(_,M,le,X,$,this.type)}D.isPointLightShadow!==!0&&this.type===Uo&&x(D,M),D.needsUpdate=!1}p=this.type,f.needsUpdate=!1,n.setRenderTarget(U,L,R)};function x(w,_){let M=e.update(v);u.defines.VSM_SAMPLES!==w.blurSamples&&(u.defines.VSM_SAMPLES=w.blurSamples,m.defines.VSM_SAMPLES=w.blurSamples,u.needsUpdate=!0,m.needsUpdate=!0),w.mapPass===null?w.mapPass=new _i(s.x,s.y,{format:lr,type:zi}):(w.mapPass.width!==w.map.width||w.mapPass.height!==w.map.height)&&w.mapPass.setSize(w.map.width,w.map.height),u.uniforms.shadow_pass.value=w.map.depthTexture,u.uniforms.resolution.value.set(w.map.width,w.map.height),u.uniforms.radius.value=w.radius,n.setRenderTarget(w.mapPass),n.clear(),n.renderBufferDirect(_,null,M,u,v,null),m.uniforms.shadow_pass.value=w.mapPass.texture,m.uniforms.resolution.value.set(w.map.width,w.map.height),m.uniforms.radius.value=w.radius,n.setRenderTarget(w.map),n.clear(),n.renderBufferDirect(_,null,M,m,v,null)}function A(w,_,M,U){let L=null,R=M.isPointLight===!0?w.customDistanceMaterial:w.customDepthMaterial;if(R!==void 0)L=R;else if(L=M.isPointLight===!0?l:a,n.localClippingEnabled&&_.clipShadows===!0&&Array.isArray(_.clippingPlanes)&&_.clippingPlanes.length!==0||_.displacementMap&&_.displacementScale!==0||_.alphaMap&&_.alphaTest>0||_.map&&_.alphaTest>0||_.alphaToCoverage===!0){let z=L.uuid,F=_.uuid,P=c[z];P===void 0&&(P={},c[z]=P);let B=P[F];B===void 0&&(B=L.clone(),P[F]=B,_.addEventListener("dispose",C)),L=B}if(L.visible=_.visible,L.wireframe=_.wireframe,U===Uo?L.side=_.shadowSide!==null?_.shadowSide:_.side:L.side=_.shadowSide!==null?_.shadowSide:d[_.side],L.alphaMap=_.alphaMap,L.alphaTest=_.alphaToCoverage===!0?.5:_.alphaTest,L.map=_.map,L.clipShadows=_.clipShadows,L.clippingPlanes=_.clippingPlanes,L.clipIntersection=_.clipIntersection,L.displacementMap=_.displacementMap,L.displacementScale=_.displacementScale,L.displacementBias=_.displacementBias,L.wireframeLinewidth=_.wireframeLinewidth,L.linewidth=_.linewidth,M.isPointLight===!0&&L.isMeshDistanceMaterial===!0){let z=n.properties.get(L);z.light=M}return L}function b(w,_,M,U,L,R){if(w.visible===!1)return;if(w.layers.test(L)&&(w.isMesh||w.isLine||w.isPoints)&&(w.castShadow||w.receiveShadow&&R===Uo)&&(!w.frustumCulled||w.intersectsFrustum(i))){w.modelViewMatrix.multiplyMatrices(M.matrixWorldInverse,w.matrixWorld);let P=e.update(w),B=w.material;if(Array.isArray(B)){let X=P.groups;for(let D=0,ne=X.length;D<ne;D++){let q=X[D],W=B[q.materialIndex];if(W&&W.visible){let $=A(w,W,U,R);w.onBeforeShadow(n,w,_,M,P,$,q),n.renderBufferDirect(M,null,P,$,w,q),w.onAfterShadow(n,w,_,M,P,$,q)}}}else if(B.visible){let X=A(w,B,U,R);w.onBeforeShadow(n,w,_,M,P,X,null),n.renderBufferDirect(M,null,P,X,w,null),w.onAfterShadow(n,w,_,M,P,X,null)}}let F=w.children;for(let P=0,B=F.length;P<B;P++)b(F[P],_,M,U,L,R)}function C(w){w.target.removeEventListener("dispose",C);for(let M in c){let U=c[M],L=w.target.uuid;L in U&&(U[L].dispose(),delete U[L])}}}function QE(n,e){function t(){let G=!1,ae=new sn,se=null,Re=new sn(0,0,0,0);return{setMask:function(Se){se!==Se&&!G&&(n.colorMask(Se,Se,Se,Se),se=Se)},setLocked:function(Se){G=Se},setClear:function(Se,Te,$e,it,ue){ue===!0&&(Se*=it,Te*=it,$e*=it),ae.set(Se,Te,$e,it),Re.equals(ae)===!1&&(n.clearColor(Se,Te,$e,it),Re.copy(ae))},reset:function(){G=!1,se=null,Re.set(-1,0,0,0)}}}function i(){let G=!1,ae=!1,se=null,Re=null,Se=null;return{setReversed:function(Te){if(ae!==Te){let $e=e.get("EXT_clip_control");Te?$e.clipControlEXT($e.LOWER_LEFT_EXT,$e.ZERO_TO_ONE_EXT):$e.clipControlEXT($e.LOWER_LEFT_EXT,$e.NEGATIVE_ONE_TO_ONE_EXT),ae=Te;let it=Se;Se=null,this.setClear(it)}},getReversed:function(){return ae},setTest:function(Te){Te?ye(n.DEPTH_TEST):Ve(n.DEPTH_TEST)},setMask:function(Te){se!==Te&&!G&&(n.depthMask(Te),se=Te)},setFunc:function(Te){if(ae&&(Te=z0[Te]),Re!==Te){switch(Te){case bc:n.depthFunc(n.NEVER);break;case Sc:n.depthFunc(n.ALWAYS);break;case Mc:n.depthFunc(n.LESS);break;case Eo:n.depthFunc(n.LEQUAL);break;case wc:n.depthFunc(n.EQUAL);break;case Ec:n.depthFunc(n.GEQUAL);break;case Tc:n.depthFunc(n.GREATER);break;case Ac:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Re=Te}},setLocked:function(Te){G=Te},setClear:function(Te){Se!==Te&&(Se=Te,ae&&(Te=1-Te),n.clearDepth(Te))},reset:function(){G=!1,se=null,Re=null,Se=null,ae=!1}}}function s(){let G=!1,ae=null,se=null,Re=null,Se=null,Te=null,$e=null,it=null,ue=null;return{setTest:function(ze){G||(ze?ye(n.STENCIL_TEST):Ve(n.STENCIL_TEST))},setMask:function(ze){ae!==ze&&!G&&(n.stencilMask(ze),ae=ze)},setFunc:function(ze,st,Pe){(se!==ze||Re!==st||Se!==Pe)&&(n.stencilFunc(ze,st,Pe),se=ze,Re=st,Se=Pe)},setOp:function(ze,st,Pe){(Te!==ze||$e!==st||it!==Pe)&&(n.stencilOp(ze,st,Pe),Te=ze,$e=st,it=Pe)},setLocked:function(ze){G=ze},setClear:function(ze){ue!==ze&&(n.clearStencil(ze),ue=ze)},reset:function(){G=!1,ae=null,se=null,Re=null,Se=null,Te=null,$e=null,it=null,ue=null}}}let r=new t,o=new i,a=new s,l={},c=new WeakMap,h={},d={},u={},m=new WeakMap,g=[],v=null,f=!1,p=null,x=null,A=null,b=null,C=null,w=null,_=null,M=new gt(0,0,0),U=0,L=!1,R=null,z=null,F=null,P=null,B=null,X=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS),D=!1,ne=0,q=n.getParameter(n.VERSION);q.indexOf("WebGL")!==-1?(ne=parseFloat(/^WebGL (\d)/.exec(q)[1]),D=ne>=1):q.indexOf("OpenGL ES")!==-1&&(ne=parseFloat(/^OpenGL ES (\d)/.exec(q)[1]),D=ne>=2);let W=null,$={},re=n.getParameter(n.SCISSOR_BOX),le=n.getParameter(n.VIEWPORT),Q=new sn().fromArray(re),me=new sn().fromArray(le);function fe(G,ae,se,Re){let Se=new Uint8Array(4),Te=n.createTexture();n.bindTexture(G,Te),n.texParameteri(G,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(G,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let $e=0;$e<se;$e++)G===n.TEXTURE_3D||G===n.TEXTURE_2D_ARRAY?n.texImage3D(ae,0,n.RGBA,1,1,Re,0,n.RGBA,n.UNSIGNED_BYTE,Se):n.texImage2D(ae+$e,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,Se);return Te}let ve={};ve[n.TEXTURE_2D]=fe(n.TEXTURE_2D,n.TEXTURE_2D,1),ve[n.TEXTURE_CUBE_MAP]=fe(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),ve[n.TEXTURE_2D_ARRAY]=fe(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),ve[n.TEXTURE_3D]=fe(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),o.setClear(1),a.setClear(0),ye(n.DEPTH_TEST),o.setFunc(Eo),Gt(!1),Rt(Ld),ye(n.CULL_FACE),Xe(Pr);function ye(G){h[G]!==!0&&(n.enable(G),h[G]=!0)}function Ve(G){h[G]!==!1&&(n.disable(G),h[G]=!1)}function Je(G,ae){return u[G]!==ae?(n.bindFramebuffer(G,ae),u[G]=ae,G===n.DRAW_FRAMEBUFFER&&(u[n.FRAMEBUFFER]=ae),G===n.FRAMEBUFFER&&(u[n.DRAW_FRAMEBUFFER]=ae),!0):!1}function Ne(G,ae){let se=g,Re=!1;if(G){se=m.get(ae),se===void 0&&(se=[],m.set(ae,se));let Se=G.textures;if(se.length!==Se.length||se[0]!==n.COLOR_ATTACHMENT0){for(let Te=0,$e=Se.length;Te<$e;Te++)se[Te]=n.COLOR_ATTACHMENT0+Te;se.length=Se.length,Re=!0}}else se[0]!==n.BACK&&(se[0]=n.BACK,Re=!0);Re&&n.drawBuffers(se)}function qe(G){return v!==G?(n.useProgram(G),v=G,!0):!1}let Qe={[Lr]:n.FUNC_ADD,[l0]:n.FUNC_SUBTRACT,[c0]:n.FUNC_REVERSE_SUBTRACT};Qe[h0]=n.MIN,Qe[u0]=n.MAX;let pe={[d0]:n.ZERO,[f0]:n.ONE,[p0]:n.SRC_COLOR,[Od]:n.SRC_ALPHA,[v0]:n.SRC_ALPHA_SATURATE,[y0]:n.DST_COLOR,[g0]:n.DST_ALPHA,[m0]:n.ONE_MINUS_SRC_COLOR,[Fd]:n.ONE_MINUS_SRC_ALPHA,[x0]:n.ONE_MINUS_DST_COLOR,[_0]:n.ONE_MINUS_DST_ALPHA,[b0]:n.CONSTANT_COLOR,[S0]:n.ONE_MINUS_CONSTANT_COLOR,[M0]:n.CONSTANT_ALPHA,[w0]:n.ONE_MINUS_CONSTANT_ALPHA};function Xe(G,ae,se,Re,Se,Te,$e,it,ue,ze){if(G===Pr){f===!0&&(Ve(n.BLEND),f=!1);return}if(f===!1&&(ye(n.BLEND),f=!0),G!==a0){if(G!==p||ze!==L){if((x!==Lr||C!==Lr)&&(n.blendEquation(n.FUNC_ADD),x=Lr,C=Lr),ze)switch(G){case Oo:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Nd:n.blendFunc(n.ONE,n.ONE);break;case Dd:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case Ud:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:ot("WebGLState: Invalid blending: ",G);break}else switch(G){case Oo:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Nd:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case Dd:ot("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Ud:ot("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:ot("WebGLState: Invalid blending: ",G);break}A=null,b=null,w=null,_=null,M.set(0,0,0),U=0,p=G,L=ze}return}Se=Se||ae,Te=Te||se,$e=$e||Re,(ae!==x||Se!==C)&&(n.blendEquationSeparate(Qe[ae],Qe[Se]),x=ae,C=Se),(se!==A||Re!==b||Te!==w||$e!==_)&&(n.blendFuncSeparate(pe[se],pe[Re],pe[Te],pe[$e]),A=se,b=Re,w=Te,_=$e),(it.equals(M)===!1||ue!==U)&&(n.blendColor(it.r,it.g,it.b,ue),M.copy(it),U=ue),p=G,L=!1}function et(G,ae){G.side===is?Ve(n.CULL_FACE):ye(n.CULL_FACE);let se=G.side===jn;ae&&(se=!se),Gt(se),G.blending===Oo&&G.transparent===!1?Xe(Pr):Xe(G.blending,G.blendEquation,G.blendSrc,G.blendDst,G.blendEquationAlpha,G.blendSrcAlpha,G.blendDstAlpha,G.blendColor,G.blendAlpha,G.premultipliedAlpha),o.setFunc(G.depthFunc),o.setTest(G.depthTest),o.setMask(G.depthWrite),r.setMask(G.colorWrite);let Re=G.stencilWrite;a.setTest(Re),Re&&(a.setMask(G.stencilWriteMask),a.setFunc(G.stencilFunc,G.stencilRef,G.stencilFuncMask),a.setOp(G.stencilFail,G.stencilZFail,G.stencilZPass)),dt(G.polygonOffset,G.polygonOffsetFactor,G.polygonOffsetUnits),G.alphaToCoverage===!0?ye(n.SAMPLE_ALPHA_TO_COVERAGE):Ve(n.SAMPLE_ALPHA_TO_COVERAGE)}function Gt(G){R!==G&&(G?n.frontFace(n.CW):n.frontFace(n.CCW),R=G)}function Rt(G){G!==s0?(ye(n.CULL_FACE),G!==z&&(G===Ld?n.cullFace(n.BACK):G===r0?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):Ve(n.CULL_FACE),z=G}function cn(G){G!==F&&(D&&n.lineWidth(G),F=G)}function dt(G,ae,se){G?(ye(n.POLYGON_OFFSET_FILL),(P!==ae||B!==se)&&(P=ae,B=se,o.getReversed()&&(ae=-ae,se=-se),n.polygonOffset(ae,se))):Ve(n.POLYGON_OFFSET_FILL)}function Pt(G){G?ye(n.SCISSOR_TEST):Ve(n.SCISSOR_TEST)}function At(G){G===void 0&&(G=n.TEXTURE0+X-1),W!==G&&(n.activeTexture(G),W=G)}function pt(G,ae,se){se===void 0&&(W===null?se=n.TEXTURE0+X-1:se=W);let Re=$[se];Re===void 0&&(Re={type:void 0,texture:void 0},$[se]=Re),(Re.type!==G||Re.texture!==ae)&&(W!==se&&(n.activeTexture(se),W=se),n.bindTexture(G,ae||ve[G]),Re.type=G,Re.texture=ae)}function k(){let G=$[W];G!==void 0&&G.type!==void 0&&(n.bindTexture(G.type,null),G.type=void 0,G.texture=void 0)}function be(){try{n.compressedTexImage2D(...arguments)}catch(G){ot("WebGLState:",G)}}function je(){try{n.compressedTexImage3D(...arguments)}catch(G){ot("WebGLState:",G)}}function ht(){try{n.texSubImage2D(...arguments)}catch(G){ot("WebGLState:",G)}}function Ae(){try{n.texSubImage3D(...arguments)}catch(G){ot("WebGLState:",G)}}function Vt(){try{n.compressedTexSubImage2D(...arguments)}catch(G){ot("WebGLState:",G)}}function We(){try{n.compressedTexSubImage3D(...arguments)}catch(G){ot("WebGLState:",G)}}function Ze(){try{n.texStorage2D(...arguments)}catch(G){ot("WebGLState:",G)}}function I(){try{n.texStorage3D(...arguments)}catch(G){ot("WebGLState:",G)}}function S(){try{n.texImage2D(...arguments)}catch(G){ot("WebGLState:",G)}}function Y(){try{n.texImage3D(...arguments)}catch(G){ot("WebGLState:",G)}}function de(G){return d[G]!==void 0?d[G]:n.getParameter(G)}function ce(G,ae){d[G]!==ae&&(n.pixelStorei(G,ae),d[G]=ae)}function Me(G){Q.equals(G)===!1&&(n.scissor(G.x,G.y,G.z,G.w),Q.copy(G))}function we(G){me.equals(G)===!1&&(n.viewport(G.x,G.y,G.z,G.w),me.copy(G))}function ie(G,ae){let se=c.get(ae);se===void 0&&(se=new WeakMap,c.set(ae,se));let Re=se.get(G);Re===void 0&&(Re=n.getUniformBlockIndex(ae,G.name),n.uniformBlockBinding(ae,Re,Re),se.set(G,Re))}function oe(G,ae,se){let Se=c.get(ae).get(G);l[Se]!==se&&(n.bindBufferBase(n.UNIFORM_BUFFER,Se,se),l[Se]=se)}function _e(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),o.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),h={},d={},W=null,$={},u={},l={},m=new WeakMap,g=[],v=null,f=!1,p=null,x=null,A=null,b=null,C=null,w=null,_=null,M=new gt(0,0,0),U=0,L=!1,R=null,z=null,F=null,P=null,B=null,Q.set(0,0,n.canvas.width,n.canvas.height),me.set(0,0,n.canvas.width,n.canvas.height),r.reset(),o.reset(),a.reset()}return{buffers:{color:r,depth:o,stencil:a},enable:ye,disable:Ve,bindFramebuffer:Je,drawBuffers:Ne,useProgram:qe,setBlending:Xe,setMaterial:et,setFlipSided:Gt,setCullFace:Rt,setLineWidth:cn,setPolygonOffset:dt,setScissorTest:Pt,activeTexture:At,bindTexture:pt,unbindTexture:k,compressedTexImage2D:be,compressedTexImage3D:je,texImage2D:S,texImage3D:Y,pixelStorei:ce,getParameter:de,updateUBOMapping:ie,uniformBlockBinding:oe,texStorage2D:Ze,texStorage3D:I,texSubImage2D:ht,texSubImage3D:Ae,compressedTexSubImage2D:Vt,compressedTexSubImage3D:We,scissor:Me,viewport:we,reset:_e}}function eT(n,e,t,i,s,r,o){let a=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new ut,h=new WeakMap,d=new Set,u,m=new WeakMap,g=new Set,v=new FinalizationRegistry(I=>g.delete(I)),f=!1;try{f=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function p(I,S){return f?new OffscreenCanvas(I,S):Aa("canvas")}function x(I,S,Y){let de=1,ce=Ze(I);if((ce.width>Y||ce.height>Y)&&(de=Y/Math.max(ce.width,ce.height)),de<1)if(typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&I instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&I instanceof ImageBitmap||typeof VideoFrame<"u"&&I instanceof VideoFrame){let Me=Math.floor(de*ce.width),we=Math.floor(de*ce.height);u===void 0&&(u=p(Me,we));let ie=S?p(Me,we):u;return ie.width=Me,ie.height=we,ie.getContext("2d").drawImage(I,0,0,Me,we),Ke("WebGLRenderer: Texture has been resized from ("+ce.width+"x"+ce.height+") to ("+Me+"x"+we+")."),ie}else return"data"in I&&Ke("WebGLRenderer: Image in DataTexture is too big ("+ce.width+"x"+ce.height+")."),I;return I}function A(I){return I.generateMipmaps}function b(I){n.generateMipmap(I)}function C(I){return I.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:I.isWebGL3DRenderTarget?n.TEXTURE_3D:I.isWebGLArrayRenderTarget||I.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function w(I,S,Y,de,ce,Me=!1){if(I!==null){if(n[I]!==void 0)return n[I];Ke("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+I+"'")}let we;de&&(we=e.get("EXT_texture_norm16"),we||Ke("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let ie=S;if(S===n.RED&&(Y===n.FLOAT&&(ie=n.R32F),Y===n.HALF_FLOAT&&(ie=n.R16F),Y===n.UNSIGNED_BYTE&&(ie=n.R8),Y===n.UNSIGNED_SHORT&&we&&(ie=we.R16_EXT),Y===n.SHORT&&we&&(ie=we.R16_SNORM_EXT)),S===n.RED_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.R8UI),Y===n.UNSIGNED_SHORT&&(ie=n.R16UI),Y===n.UNSIGNED_INT&&(ie=n.R32UI),Y===n.BYTE&&(ie=n.R8I),Y===n.SHORT&&(ie=n.R16I),Y===n.INT&&(ie=n.R32I)),S===n.RG&&(Y===n.FLOAT&&(ie=n.RG32F),Y===n.HALF_FLOAT&&(ie=n.RG16F),Y===n.UNSIGNED_BYTE&&(ie=n.RG8),Y===n.UNSIGNED_SHORT&&we&&(ie=we.RG16_EXT),Y===n.SHORT&&we&&(ie=we.RG16_SNORM_EXT)),S===n.RG_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.RG8UI),Y===n.UNSIGNED_SHORT&&(ie=n.RG16UI),Y===n.UNSIGNED_INT&&(ie=n.RG32UI),Y===n.BYTE&&(ie=n.RG8I),Y===n.SHORT&&(ie=n.RG16I),Y===n.INT&&(ie=n.RG32I)),S===n.RGB_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.RGB8UI),Y===n.UNSIGNED_SHORT&&(ie=n.RGB16UI),Y===n.UNSIGNED_INT&&(ie=n.RGB32UI),Y===n.BYTE&&(ie=n.RGB8I),Y===n.SHORT&&(ie=n.RGB16I),Y===n.INT&&(ie=n.RGB32I)),S===n.RGBA_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.RGBA8UI),Y===n.UNSIGNED_SHORT&&(ie=n.RGBA16UI),Y===n.UNSIGNED_INT&&(ie=n.RGBA32UI),Y===n.BYTE&&(ie=n.RGBA8I),Y===n.SHORT&&(ie=n.RGBA16I),Y===n.INT&&(ie=n.RGBA32I)),S===n.RGB&&(Y===n.UNSIGNED_SHORT&&we&&(ie=we.RGB16_EXT),Y===n.SHORT&&we&&(ie=we.RGB16_SNORM_EXT),Y===n.UNSIGNED_INT_5_9_9_9_REV&&(ie=n.RGB9_E5),Y===n.UNSIGNED_INT_10F_11F_11F_REV&&(ie=n.R11F_G11F_B10F)),S===n.RGBA){let oe=Me?Ea:Tt.getTransfer(ce);Y===n.FLOAT&&(ie=n.RGBA32F),Y===n.HALF_FLOAT&&(ie=n.RGBA16F),Y===n.UNSIGNED_BYTE&&(ie=oe===Ft?n.SRGB8_ALPHA8:n.RGBA8),Y===n.UNSIGNED_SHORT&&we&&(ie=we.RGBA16_EXT),Y===n.SHORT&&we&&(ie=we.RGBA16_SNORM_EXT),Y===n.UNSIGNED_SHORT_4_4_4_4&&(ie=n.RGBA4),Y===n.UNSIGNED_SHORT_5_5_5_1&&(ie=n.RGB5_A1)}return(ie===n.R16F||ie===n.R32F||ie===n.RG16F||ie===n.RG32F||ie===n.RGBA16F||ie===n.RGBA32F)&&e.get("EXT_color_buffer_float"),ie}function _(I,S){let Y;return I?S===null||S===Bi||S===Dr?Y=n.DEPTH24_STENCIL8:S===ki?Y=n.DEPTH32F_STENCIL8:S===Bo&&(Y=n.DEPTH24_STENCIL8,Ke("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):S===null||S===Bi||S===Dr?Y=n.DEPTH_COMPONENT24:S===ki?Y=n.DEPTH_COMPONENT32F:S===Bo&&(Y=n.DEPTH_COMPONENT16),Y}function M(I,S){return A(I)===!0||I.isFramebufferTexture&&I.minFilter!==Dn&&I.minFilter!==Jn?Math.log2(Math.max(S.width,S.height))+1:I.mipmaps.length>0?I.mipmaps.length:I.isCompressedTexture&&Array.isArray(I.image)?S.mipmaps.length:1}function U(I){let S=new WeakRef(I);i.get(I).__ref=S,g.add(S),v.register(I,S,S)}function L(I){let S=i.get(I).__ref;S!==void 0&&(g.delete(S),v.unregister(S))}function R(I){F(I.target)}function z(I){P(I.target)}function F(I){I.removeEventListener("dispose",R),L(I),X(I),I.isVideoTexture&&h.delete(I),I.isHTMLTexture&&d.delete(I)}function P(I){I.removeEventListener("dispose",z),L(I),ne(I)}function B(){for(let I of g){let S=I.deref();S!==void 0&&(S.isRenderTarget===!0?P(S):F(S))}g.clear(),d.clear()}function X(I){let S=i.get(I);if(S.__webglInit===void 0)return;let Y=I.source,de=m.get(Y);if(de){let ce=de[S.__cacheKey];ce.usedTimes--,ce.usedTimes===0&&D(I),Object.keys(de).length===0&&m.delete(Y)}i.remove(I)}function D(I){let S=i.get(I);n.deleteTexture(S.__webglTexture);let Y=I.source,de=m.get(Y);delete de[S.__cacheKey],o.memory.textures--}function ne(I){let S=i.get(I);S.__depthDisposeCallback&&S.__depthDisposeCallback();let Y=I.depthTexture;if(Y&&Y.renderTarget===I&&F(Y),I.isWebGLCubeRenderTarget)for(let ce=0;ce<6;ce++){if(Array.isArray(S.__webglFramebuffer[ce]))for(let Me=0;Me<S.__webglFramebuffer[ce].length;Me++)n.deleteFramebuffer(S.__webglFramebuffer[ce][Me]);else n.deleteFramebuffer(S.__webglFramebuffer[ce]);S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer[ce])}else{if(Array.isArray(S.__webglFramebuffer))for(let ce=0;ce<S.__webglFramebuffer.length;ce++)n.deleteFramebuffer(S.__webglFramebuffer[ce]);else n.deleteFramebuffer(S.__webglFramebuffer);if(S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer),S.__webglMultisampledFramebuffer&&n.deleteFramebuffer(S.__webglMultisampledFramebuffer),S.__webglColorRenderbuffer)for(let ce=0;ce<S.__webglColorRenderbuffer.length;ce++)S.__webglColorRenderbuffer[ce]&&n.deleteRenderbuffer(S.__webglColorRenderbuffer[ce]);S.__webglDepthRenderbuffer&&n.deleteRenderbuffer(S.__webglDepthRenderbuffer)}let de=I.textures;for(let ce=0,Me=de.length;ce<Me;ce++){let we=i.get(de[ce]);we.__webglTexture&&(n.deleteTexture(we.__webglTexture),o.memory.textures--),i.remove(de[ce])}i.remove(I)}let q=0;function W(){q=0}function $(){return q}function re(I){q=I}function le(){let I=q;return I>=s.maxTextures&&Ke("WebGLTextures: Trying to use "+(I+1)+" texture units while this GPU supports only "+s.maxTextures),q+=1,I}function Q(I){let S=[];return S.push(I.wrapS),S.push(I.wrapT),S.push(I.wrapR||0),S.push(I.magFilter),S.push(I.minFilter),S.push(I.anisotropy),S.push(I.internalFormat),S.push(I.format),S.push(I.type),S.push(I.generateMipmaps),S.push(I.mipmapsAutoUpdate),S.push(I.premultiplyAlpha),S.push(I.flipY),S.push(I.unpackAlignment),S.push(I.colorSpace),S.join()}function me(I,S){let Y=i.get(I);if(I.isVideoTexture&&Vt(I),I.isRenderTargetTexture===!1&&I.isExternalTexture!==!0&&I.version>0&&Y.__version!==I.version){let de=I.image;if(de===null)Ke("WebGLRenderer: Texture marked for update but no image data found.");else if(de.complete===!1)Ke("WebGLRenderer: Texture marked for update but image is incomplete");else{et(Y,I,S);return}}else I.isExternalTexture&&(Y.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D,Y.__webglTexture,n.TEXTURE0+S)}function fe(I,S){let Y=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&Y.__version!==I.version){et(Y,I,S);return}else I.isExternalTexture&&(Y.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D_ARRAY,Y.__webglTexture,n.TEXTURE0+S)}function ve(I,S){let Y=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&Y.__version!==I.version){et(Y,I,S);return}t.bindTexture(n.TEXTURE_3D,Y.__webglTexture,n.TEXTURE0+S)}function ye(I,S){let Y=i.get(I);if(I.version>0&&Y.__version!==I.version){Gt(Y,I,S);return}t.bindTexture(n.TEXTURE_CUBE_MAP,Y.__webglTexture,n.TEXTURE0+S)}let Ve={[Rc]:n.REPEAT,[es]:n.CLAMP_TO_EDGE,[Cc]:n.MIRRORED_REPEAT},Je={[Dn]:n.NEAREST,[A0]:n.NEAREST_MIPMAP_NEAREST,[Xa]:n.NEAREST_MIPMAP_LINEAR,[Jn]:n.LINEAR,[sh]:n.LINEAR_MIPMAP_NEAREST,[Ts]:n.LINEAR_MIPMAP_LINEAR},Ne={[P0]:n.NEVER,[sf]:n.ALWAYS,[L0]:n.LESS,[tf]:n.LEQUAL,[N0]:n.EQUAL,[nf]:n.GEQUAL,[D0]:n.GREATER,[U0]:n.NOTEQUAL};function qe(I,S){if(S.type===ki&&e.has("OES_texture_float_linear")===!1&&(S.magFilter===Jn||S.magFilter===sh||S.magFilter===Xa||S.magFilter===Ts||S.minFilter===Jn||S.minFilter===sh||S.minFilter===Xa||S.minFilter===Ts)&&Ke("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(I,n.TEXTURE_WRAP_S,Ve[S.wrapS]),n.texParameteri(I,n.TEXTURE_WRAP_T,Ve[S.wrapT]),(I===n.TEXTURE_3D||I===n.TEXTURE_2D_ARRAY)&&n.texParameteri(I,n.TEXTURE_WRAP_R,Ve[S.wrapR]),n.texParameteri(I,n.TEXTURE_MAG_FILTER,Je[S.magFilter]),n.texParameteri(I,n.TEXTURE_MIN_FILTER,Je[S.minFilter]),S.compareFunction&&(n.texParameteri(I,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(I,n.TEXTURE_COMPARE_FUNC,Ne[S.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(S.magFilter===Dn||S.minFilter!==Xa&&S.minFilter!==Ts||S.type===ki&&e.has("OES_texture_float_linear")===!1)return;if(S.anisotropy>1||i.get(S).__currentAnisotropy){let Y=e.get("EXT_texture_filter_anisotropic");n.texParameterf(I,Y.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(S.anisotropy,s.getMaxAnisotropy())),i.get(S).__currentAnisotropy=S.anisotropy}}}function Qe(I,S){let Y=!1;I.__webglInit===void 0&&(I.__webglInit=!0,S.addEventListener("dispose",R),U(S));let de=S.source,ce=m.get(de);ce===void 0&&(ce={},m.set(de,ce));let Me=Q(S);if(Me!==I.__cacheKey){ce[Me]===void 0&&(ce[Me]={texture:n.createTexture(),usedTimes:0},o.memory.textures++,Y=!0),ce[Me].usedTimes++;let we=ce[I.__cacheKey];we!==void 0&&(ce[I.__cacheKey].usedTimes--,we.usedTimes===0&&D(S)),I.__cacheKey=Me,I.__webglTexture=ce[Me].texture}return Y}function pe(I,S,Y){return Math.floor(Math.floor(I/Y)/S)}function Xe(I,S,Y,de){let Me=I.updateRanges;if(Me.length===0)t.texSubImage2D(n.TEXTURE_2D,0,0,0,S.width,S.height,Y,de,S.data);else{Me.sort((G,ae)=>G.start-ae.start);let we=0;for(let G=1;G<Me.length;G++){let ae=Me[we],se=Me[G],Re=ae.start+ae.count,Se=pe(se.start,S.width,4),Te=pe(ae.start,S.width,4);se.start<=Re+1&&Se===Te&&pe(se.start+se.count-1,S.width,4)===Se?ae.count=Math.max(ae.count,se.start+se.count-ae.start):(++we,Me[we]=se)}Me.length=we+1;let ie=t.getParameter(n.UNPACK_ROW_LENGTH),oe=t.getParameter(n.UNPACK_SKIP_PIXELS),_e=t.getParameter(n.UNPACK_SKIP_ROWS);t.pixelStorei(n.UNPACK_ROW_LENGTH,S.width);for(let G=0,ae=Me.length;G<ae;G++){let se=Me[G],Re=Math.floor(se.start/4),Se=Math.ceil(se.count/4),Te=Re%S.width,$e=Math.floor(Re/S.width),it=Se,ue=1;t.pixelStorei(n.UNPACK_SKIP_PIXELS,Te),t.pixelStorei(n.UNPACK_SKIP_ROWS,$e),t.texSubImage2D(n.TEXTURE_2D,0,Te,$e,it,ue,Y,de,S.data)}I.clearUpdateRanges(),t.pixelStorei(n.UNPACK_ROW_LENGTH,ie),t.pixelStorei(n.UNPACK_SKIP_PIXELS,oe),t.pixelStorei(n.UNPACK_SKIP_ROWS,_e)}}function et(I,S,Y){let de=n.TEXTURE_2D;(S.isDataArrayTexture||S.isCompressedArrayTexture)&&(de=n.TEXTURE_2D_ARRAY),S.isData3DTexture&&(de=n.TEXTURE_3D);let ce=Qe(I,S),Me=S.source;t.bindTexture(de,I.__webglTexture,n.TEXTURE0+Y);let we=i.get(Me);if(Me.version!==we.__version||ce===!0){if(t.activeTexture(n.TEXTURE0+Y),(typeof ImageBitmap<"u"&&S.image instanceof ImageBitmap)===!1){let ue=Tt.getPrimaries(Tt.workingColorSpace),ze=S.colorSpace===Rs?null:Tt.getPrimaries(S.colorSpace),st=S.colorSpace===Rs||ue===ze?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,st)}t.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment);let oe=x(S.image,!1,s.maxTextureSize);oe=We(S,oe);let _e=r.convert(S.format,S.colorSpace),G=r.convert(S.type),ae=w(S.internalFormat,_e,G,S.normalized,S.colorSpace,S.isVideoTexture);qe(de,S);let se,Re=S.mipmaps,Se=S.isVideoTexture!==!0,Te=we.__version===void 0||ce===!0,$e=Me.dataReady,it=M(S,oe);if(S.isDepthTexture)ae=_(S.format===As,S.type),Te&&(Se?t.texStorage2D(n.TEXTURE_2D,1,ae,oe.width,oe.height):t.texImage2D(n.TEXTURE_2D,0,ae,oe.width,oe.height,0,_e,G,null));else if(S.isDataTexture)if(Re.length>0){Se&&Te&&t.texStorage2D(n.TEXTURE_2D,it,ae,Re[0].width,Re[0].height);for(let ue=0,ze=Re.length;ue<ze;ue++)se=Re[ue],Se?$e&&t.texSubImage2D(n.TEXTURE_2D,ue,0,0,se.width,se.height,_e,G,se.data):t.texImage2D(n.TEXTURE_2D,ue,ae,se.width,se.height,0,_e,G,se.data);S.generateMipmaps=!1}else Se?(Te&&t.texStorage2D(n.TEXTURE_2D,it,ae,oe.width,oe.height),$e&&Xe(S,oe,_e,G)):t.texImage2D(n.TEXTURE_2D,0,ae,oe.width,oe.height,0,_e,G,oe.data);else if(S.isCompressedTexture)if(S.isCompressedArrayTexture){Se&&Te&&t.texStorage3D(n.TEXTURE_2D_ARRAY,it,ae,Re[0].width,Re[0].height,oe.depth);for(let ue=0,ze=Re.length;ue<ze;ue++)if(se=Re[ue],S.format!==Gi)if(_e!==null)if(Se){if($e)if(S.layerUpdates.size>0){let st=pf(se.width,se.height,S.format,S.type);for(let Pe of S.layerUpdates){let ft=se.data.subarray(Pe*st/se.data.BYTES_PER_ELEMENT,(Pe+1)*st/se.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ue,0,0,Pe,se.width,se.height,1,_e,ft)}}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ue,0,0,0,se.width,se.height,oe.depth,_e,se.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,ue,ae,se.width,se.height,oe.depth,0,se.data,0,0);else Ke("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else Se?$e&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,ue,0,0,0,se.width,se.height,oe.depth,_e,G,se.data):t.texImage3D(n.TEXTURE_2D_ARRAY,ue,ae,se.width,se.height,oe.depth,0,_e,G,se.data);S.layerUpdates.size>0&&S.clearLayerUpdates()}else{Se&&Te&&t.texStorage2D(n.TEXTURE_2D,it,ae,Re[0].width,Re[0].height);for(let ue=0,ze=Re.length;ue<ze;ue++)se=Re[ue],S.format!==Gi?_e!==null?Se?$e&&t.compressedTexSubImage2D(n.TEXTURE_2D,ue,0,0,se.width,se.height,_e,se.data):t.compressedTexImage2D(n.TEXTURE_2D,ue,ae,se.width,se.height,0,se.data):Ke("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):Se?$e&&t.texSubImage2D(n.TEXTURE_2D,ue,0,0,se.width,se.height,_e,G,se.data):t.texImage2D(n.TEXTURE_2D,ue,ae,se.width,se.height,0,_e,G,se.data)}else if(S.isDataArrayTexture)if(Se){if(Te&&t.texStorage3D(n.TEXTURE_2D_ARRAY,it,ae,oe.width,oe.height,oe.depth),$e)if(S.layerUpdates.size>0){let ue=pf(oe.width,oe.height,S.format,S.type);for(let ze of S.layerUpdates){let st=oe.data.subarray(ze*ue/oe.data.BYTES_PER_ELEMENT,(ze+1)*ue/oe.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,ze,oe.width,oe.height,1,_e,G,st)}S.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,oe.width,oe.height,oe.depth,_e,G,oe.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,ae,oe.width,oe.height,oe.depth,0,_e,G,oe.data);else if(S.isData3DTexture)Se?(Te&&t.texStorage3D(n.TEXTURE_3D,it,ae,oe.width,oe.height,oe.depth),$e&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,oe.width,oe.height,oe.depth,_e,G,oe.data)):t.texImage3D(n.TEXTURE_3D,0,ae,oe.width,oe.height,oe.depth,0,_e,G,oe.data);else if(S.isFramebufferTexture){if(Te)if(Se)t.texStorage2D(n.TEXTURE_2D,it,ae,oe.width,oe.height);else{let ue=oe.width,ze=oe.height;for(let st=0;st<it;st++)t.texImage2D(n.TEXTURE_2D,st,ae,ue,ze,0,_e,G,null),ue>>=1,ze>>=1}}else if(S.isHTMLTexture){if("texElementImage2D"in n){let ue=n.canvas;if(ue.hasAttribute("layoutsubtree")||ue.setAttribute("layoutsubtree","true"),oe.parentNode!==ue){ue.appendChild(oe),d.add(S),ue.onpaint=ze=>{let st=ze.changedElements;for(let Pe of d)st.includes(Pe.image)&&(Pe.needsUpdate=!0)},ue.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,oe);else{let st=n.RGBA,Pe=n.RGBA,ft=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,st,Pe,ft,oe)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Re.length>0){if(Se&&Te){let ue=Ze(Re[0]);t.texStorage2D(n.TEXTURE_2D,it,ae,ue.width,ue.height)}for(let ue=0,ze=Re.length;ue<ze;ue++)se=Re[ue],Se?$e&&t.texSubImage2D(n.TEXTURE_2D,ue,0,0,_e,G,se):t.texImage2D(n.TEXTURE_2D,ue,ae,_e,G,se);S.generateMipmaps=!1}else if(Se){if(Te){let ue=Ze(oe);t.texStorage2D(n.TEXTURE_2D,it,ae,ue.width,ue.height)}$e&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,_e,G,oe)}else t.texImage2D(n.TEXTURE_2D,0,ae,_e,G,oe);A(S)&&S.mipmapsAutoUpdate===!0&&b(de),we.__version=Me.version,S.onUpdate&&S.onUpdate(S)}I.__version=S.version}function Gt(I,S,Y){if(S.image.length!==6)return;let de=Qe(I,S),ce=S.source;t.bindTexture(n.TEXTURE_CUBE_MAP,I.__webglTexture,n.TEXTURE0+Y);let Me=i.get(ce);if(ce.version!==Me.__version||de===!0){t.activeTexture(n.TEXTURE0+Y);let we=Tt.getPrimaries(Tt.workingColorSpace),ie=S.colorSpace===Rs?null:Tt.getPrimaries(S.colorSpace),oe=S.colorSpace===Rs||we===ie?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,oe);let _e=S.isCompressedTexture||S.image[0].isCompressedTexture,G=S.image[0]&&S.image[0].isDataTexture,ae=[];for(let Pe=0;Pe<6;Pe++)!_e&&!G?ae[Pe]=x(S.image[Pe],!0,s.maxCubemapSize):ae[Pe]=G?S.image[Pe].image:S.image[Pe],ae[Pe]=We(S,ae[Pe]);let se=ae[0],Re=r.convert(S.format,S.colorSpace),Se=r.convert(S.type),Te=w(S.internalFormat,Re,Se,S.normalized,S.colorSpace),$e=S.isVideoTexture!==!0,it=Me.__version===void 0||de===!0,ue=ce.dataReady,ze=M(S,se);qe(n.TEXTURE_CUBE_MAP,S);let st;if(S.isDepthTexture){if(Te=_(S.format===As,S.type),it)if($e)t.texStorage2D(n.TEXTURE_CUBE_MAP,1,Te,se.width,se.height);else for(let Pe=0;Pe<6;Pe++)t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,Te,se.width,se.height,0,Re,Se,null)}else if(_e){$e&&it&&t.texStorage2D(n.TEXTURE_CUBE_MAP,ze,Te,se.width,se.height);for(let Pe=0;Pe<6;Pe++){st=ae[Pe].mipmaps;for(let ft=0;ft<st.length;ft++){let $t=st[ft];S.format!==Gi?Re!==null?$e?ue&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft,0,0,$t.width,$t.height,Re,$t.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft,Te,$t.width,$t.height,0,$t.data):Ke("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft,0,0,$t.width,$t.height,Re,Se,$t.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft,Te,$t.width,$t.height,0,Re,Se,$t.data)}}}else{if(st=S.mipmaps,$e&&it){st.length>0&&ze++;let Pe=Ze(ae[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,ze,Te,Pe.width,Pe.height)}for(let Pe=0;Pe<6;Pe++)if(G){$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,0,0,ae[Pe].width,ae[Pe].height,Re,Se,ae[Pe].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,Te,ae[Pe].width,ae[Pe].height,0,Re,Se,ae[Pe].data);for(let ft=0;ft<st.length;ft++){let Wn=st[ft].image[Pe].image;$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft+1,0,0,Wn.width,Wn.height,Re,Se,Wn.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft+1,Te,Wn.width,Wn.height,0,Re,Se,Wn.data)}}else{$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,0,0,Re,Se,ae[Pe]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,Te,Re,Se,ae[Pe]);for(let ft=0;ft<st.length;ft++){let $t=st[ft];$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft+1,0,0,Re,Se,$t.image[Pe]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,ft+1,Te,Re,Se,$t.image[Pe])}}}A(S)&&S.mipmapsAutoUpdate===!0&&b(n.TEXTURE_CUBE_MAP),Me.__version=ce.version,S.onUpdate&&S.onUpdate(S)}I.__version=S.version}function Rt(I,S,Y,de,ce,Me){let we=r.convert(Y.format,Y.colorSpace),ie=r.convert(Y.type),oe=w(Y.internalFormat,we,ie,Y.normalized,Y.colorSpace),_e=i.get(S),G=i.get(Y);if(G.__renderTarget=S,!_e.__hasExternalTextures){let ae=Math.max(1,S.width>>Me),se=Math.max(1,S.height>>Me);ce===n.TEXTURE_3D||ce===n.TEXTURE_2D_ARRAY?t.texImage3D(ce,Me,oe,ae,se,S.depth,0,we,ie,null):t.texImage2D(ce,Me,oe,ae,se,0,we,ie,null)}t.bindFramebuffer(n.FRAMEBUFFER,I),Ae(S)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,de,ce,G.__webglTexture,0,ht(S)):(ce===n.TEXTURE_2D||ce>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&ce<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,de,ce,G.__webglTexture,Me),t.bindFramebuffer(n.FRAMEBUFFER,null)}function cn(I,S,Y){if(n.bindRenderbuffer(n.RENDERBUFFER,I),S.depthBuffer){let de=S.depthTexture,ce=de&&de.isDepthTexture?de.type:null,Me=_(S.stencilBuffer,ce),we=S.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;Ae(S)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ht(S),Me,S.width,S.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,ht(S),Me,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,Me,S.width,S.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,we,n.RENDERBUFFER,I)}else{let de=S.textures;for(let ce=0;ce<de.length;ce++){let Me=de[ce],we=r.convert(Me.format,Me.colorSpace),ie=r.convert(Me.type),oe=w(Me.internalFormat,we,ie,Me.normalized,Me.colorSpace);Ae(S)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ht(S),oe,S.width,S.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,ht(S),oe,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,oe,S.width,S.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function dt(I,S,Y){let de=S.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(n.FRAMEBUFFER,I),!(S.depthTexture&&S.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let ce=i.get(S.depthTexture);ce.__renderTarget=S;let Me=de?S.depthTexture.image[0]:S.depthTexture.image;(!ce.__webglTexture||Me.width!==S.width||Me.height!==S.height)&&(Me.width=S.width,Me.height=S.height,S.depthTexture.needsUpdate=!0),de?ye(S.depthTexture,0):me(S.depthTexture,0);let we=ce.__webglTexture,ie=ht(S),oe=de?n.TEXTURE_CUBE_MAP_POSITIVE_X+Y:n.TEXTURE_2D,_e=S.depthTexture.format===As?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(S.depthTexture.format===Ms)Ae(S)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,_e,oe,we,0,ie):n.framebufferTexture2D(n.FRAMEBUFFER,_e,oe,we,0);else if(S.depthTexture.format===As)Ae(S)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,_e,oe,we,0,ie):n.framebufferTexture2D(n.FRAMEBUFFER,_e,oe,we,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function Pt(I){let S=i.get(I),Y=I.isWebGLCubeRenderTarget===!0;if(S.__boundDepthTexture!==I.depthTexture){let de=I.depthTexture;if(S.__depthDisposeCallback&&S.__depthDisposeCallback(),de){let ce=()=>{delete S.__boundDepthTexture,delete S.__depthDisposeCallback,de.removeEventListener("dispose",ce)};de.addEventListener("dispose",ce),S.__depthDisposeCallback=ce}S.__boundDepthTexture=de}if(I.depthTexture&&!S.__autoAllocateDepthBuffer)if(Y)for(let de=0;de<6;de++)dt(S.__webglFramebuffer[de],I,de);else I.texture.mipmaps.length>0?dt(S.__webglFramebuffer[0],I,0):dt(S.__webglFramebuffer,I,0);else if(Y){S.__webglDepthbuffer=[];for(let de=0;de<6;de++)if(t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[de]),S.__webglDepthbuffer[de]===void 0)S.__webglDepthbuffer[de]=n.createRenderbuffer(),cn(S.__webglDepthbuffer[de],I,!1);else{let ce=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Me=S.__webglDepthbuffer[de];n.bindRenderbuffer(n.RENDERBUFFER,Me),n.framebufferRenderbuffer(n.FRAMEBUFFER,ce,n.RENDERBUFFER,Me)}}else if(I.texture.mipmaps.length>0?t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[0]):t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer),S.__webglDepthbuffer===void 0)S.__webglDepthbuffer=n.createRenderbuffer(),cn(S.__webglDepthbuffer,I,!1);else{let ce=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Me=S.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,Me),n.framebufferRenderbuffer(n.FRAMEBUFFER,ce,n.RENDERBUFFER,Me)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function At(I,S,Y){let de=i.get(I);S!==void 0&&Rt(de.__webglFramebuffer,I,I.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),Y!==void 0&&Pt(I)}function pt(I){let S=I.texture,Y=i.get(I),de=i.get(S);I.addEventListener("dispose",z),U(I);let ce=I.textures,Me=I.isWebGLCubeRenderTarget===!0,we=ce.length>1;if(we||(de.__webglTexture===void 0&&(de.__webglTexture=n.createTexture()),de.__version=S.version,o.memory.textures++),Me){Y.__webglFramebuffer=[];for(let ie=0;ie<6;ie++)if(S.mipmaps.length>0){Y.__webglFramebuffer[ie]=[];for(let oe=0;oe<S.mipmaps.length;oe++)Y.__webglFramebuffer[ie][oe]=n.createFramebuffer()}else Y.__webglFramebuffer[ie]=n.createFramebuffer()}else{if(S.mipmaps.length>0){Y.__webglFramebuffer=[];for(let ie=0;ie<S.mipmaps.length;ie++)Y.__webglFramebuffer[ie]=n.createFramebuffer()}else Y.__webglFramebuffer=n.createFramebuffer();if(we)for(let ie=0,oe=ce.length;ie<oe;ie++){let _e=i.get(ce[ie]);_e.__webglTexture===void 0&&(_e.__webglTexture=n.createTexture(),o.memory.textures++)}if(I.samples>0&&Ae(I)===!1){Y.__webglMultisampledFramebuffer=n.createFramebuffer(),Y.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,Y.__webglMultisampledFramebuffer);for(let ie=0;ie<ce.length;ie++){let oe=ce[ie];Y.__webglColorRenderbuffer[ie]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,Y.__webglColorRenderbuffer[ie]);let _e=r.convert(oe.format,oe.colorSpace),G=r.convert(oe.type),ae=w(oe.internalFormat,_e,G,oe.normalized,oe.colorSpace,I.isXRRenderTarget===!0),se=ht(I);n.renderbufferStorageMultisample(n.RENDERBUFFER,se,ae,I.width,I.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ie,n.RENDERBUFFER,Y.__webglColorRenderbuffer[ie])}n.bindRenderbuffer(n.RENDERBUFFER,null),I.depthBuffer&&(Y.__webglDepthRenderbuffer=n.createRenderbuffer(),cn(Y.__webglDepthRenderbuffer,I,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(Me){t.bindTexture(n.TEXTURE_CUBE_MAP,de.__webglTexture),qe(n.TEXTURE_CUBE_MAP,S);for(let ie=0;ie<6;ie++)if(S.mipmaps.length>0)for(let oe=0;oe<S.mipmaps.length;oe++)Rt(Y.__webglFramebuffer[ie][oe],I,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ie,oe);else Rt(Y.__webglFramebuffer[ie],I,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ie,0);A(S)?b(n.TEXTURE_CUBE_MAP):S.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}else if(we){for(let ie=0,oe=ce.length;ie<oe;ie++){let _e=ce[ie],G=i.get(_e),ae=n.TEXTURE_2D;(I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(ae=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ae,G.__webglTexture),qe(ae,_e),Rt(Y.__webglFramebuffer,I,_e,n.COLOR_ATTACHMENT0+ie,ae,0),A(_e)&&b(ae)}t.unbindTexture()}else{let ie=n.TEXTURE_2D;if((I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(ie=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ie,de.__webglTexture),qe(ie,S),S.mipmaps.length>0)for(let oe=0;oe<S.mipmaps.length;oe++)Rt(Y.__webglFramebuffer[oe],I,S,n.COLOR_ATTACHMENT0,ie,oe);else Rt(Y.__webglFramebuffer,I,S,n.COLOR_ATTACHMENT0,ie,0);A(S)?b(ie):S.mipmaps.length>0&&n.texParameteri(ie,n.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}I.depthBuffer&&Pt(I)}function k(I){let S=I.textures;for(let Y=0,de=S.length;Y<de;Y++){let ce=S[Y];if(A(ce)&&ce.mipmapsAutoUpdate===!0){let Me=C(I),we=i.get(ce).__webglTexture;t.bindTexture(Me,we),b(Me),t.unbindTexture()}}}let be=[];function je(I){if(I.samples>0){if(Ae(I)===!1){let S=I.textures,Y=I.width,de=I.height,ce=n.COLOR_BUFFER_BIT,Me=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,we=i.get(I),ie=S.length>1;if(ie)for(let _e=0;_e<S.length;_e++)t.bindFramebuffer(n.FRAMEBUFFER,we.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+_e,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,we.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+_e,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,we.__webglMultisampledFramebuffer),I.texture.mipmaps.length>0?t.bindFramebuffer(n.DRAW_FRAMEBUFFER,we.__webglFramebuffer[0]):t.bindFramebuffer(n.DRAW_FRAMEBUFFER,we.__webglFramebuffer);for(let _e=0;_e<S.length;_e++){if(I.resolveDepthBuffer&&(I.depthBuffer&&(ce|=n.DEPTH_BUFFER_BIT),I.stencilBuffer&&I.resolveStencilBuffer&&(ce|=n.STENCIL_BUFFER_BIT)),ie){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,we.__webglColorRenderbuffer[_e]);let G=i.get(S[_e]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,G,0)}n.blitFramebuffer(0,0,Y,de,0,0,Y,de,ce,n.NEAREST),l===!0&&(be.length=0,be.push(n.COLOR_ATTACHMENT0+_e),I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&be.push(Me),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,be))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),ie)for(let _e=0;_e<S.length;_e++){t.bindFramebuffer(n.FRAMEBUFFER,we.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+_e,n.RENDERBUFFER,we.__webglColorRenderbuffer[_e]);let G=i.get(S[_e]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,we.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+_e,n.TEXTURE_2D,G,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,we.__webglMultisampledFramebuffer)}else if(I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&l){let S=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[S])}}}function ht(I){return Math.min(s.maxSamples,I.samples)}function Ae(I){let S=i.get(I);return I.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&S.__useRenderToTexture!==!1}function Vt(I){let S=o.render.frame;h.get(I)!==S&&(h.set(I,S),I.update())}function We(I,S){let Y=I.colorSpace,de=I.format,ce=I.type;return I.isCompressedTexture===!0||I.isVideoTexture===!0||Y!==wa&&Y!==Rs&&(Tt.getTransfer(Y)===Ft?(de!==Gi||ce!==xi)&&Ke("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):ot("WebGLTextures: Unsupported texture color space:",Y)),S}function Ze(I){return typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement?(c.width=I.naturalWidth||I.width,c.height=I.naturalHeight||I.height):typeof VideoFrame<"u"&&I instanceof VideoFrame?(c.width=I.displayWidth,c.height=I.displayHeight):(c.width=I.width,c.height=I.height),c}this.allocateTextureUnit=le,this.resetTextureUnits=W,this.getTextureUnits=$,this.setTextureUnits=re,this.setTexture2D=me,this.setTexture2DArray=fe,this.setTexture3D=ve,this.setTextureCube=ye,this.rebindTextures=At,this.setupRenderTarget=pt,this.updateRenderTargetMipmap=k,this.updateMultisampleRenderTarget=je,this.setupDepthRenderbuffer=Pt,this.setupFrameBufferTexture=Rt,this.useMultisampledRTT=Ae,this.dispose=B}function tT(n,e){function t(i,s=Rs){let r,o=Tt.getTransfer(s);if(i===xi)return n.UNSIGNED_BYTE;if(i===oh)return n.UNSIGNED_SHORT_4_4_4_4;if(i===ah)return n.UNSIGNED_SHORT_5_5_5_1;if(i===Zd)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===Kd)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===qd)return n.BYTE;if(i===Yd)return n.SHORT;if(i===Bo)return n.UNSIGNED_SHORT;if(i===rh)return n.INT;if(i===Bi)return n.UNSIGNED_INT;if(i===ki)return n.FLOAT;if(i===zi)return n.HALF_FLOAT;if(i===Jd)return n.ALPHA;if(i===jd)return n.RGB;if(i===Gi)return n.RGBA;if(i===Ms)return n.DEPTH_COMPONENT;if(i===As)return n.DEPTH_STENCIL;if(i===Qd)return n.RED;if(i===lh)return n.RED_INTEGER;if(i===lr)return n.RG;if(i===ch)return n.RG_INTEGER;if(i===hh)return n.RGBA_INTEGER;if(i===$a||i===qa||i===Ya||i===Za)if(o===Ft)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(i===$a)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===qa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===Ya)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===Za)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(i===$a)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===qa)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===Ya)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===Za)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===uh||i===dh||i===fh||i===ph)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(i===uh)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===dh)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===fh)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===ph)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===mh||i===gh||i===_h||i===yh||i===xh||i===Ka||i===vh)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(i===mh||i===gh)return o===Ft?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(i===_h)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(i===yh)return r.COMPRESSED_R11_EAC;if(i===xh)return r.COMPRESSED_SIGNED_R11_EAC;if(i===Ka)return r.COMPRESSED_RG11_EAC;if(i===vh)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===bh||i===Sh||i===Mh||i===wh||i===Eh||i===Th||i===Ah||i===Rh||i===Ch||i===Ih||i===Ph||i===Lh||i===Nh||i===Dh)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(i===bh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===Sh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===Mh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===wh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===Eh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===Th)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===Ah)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===Rh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===Ch)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===Ih)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===Ph)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===Lh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===Nh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===Dh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===Uh||i===Oh||i===Fh)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(i===Uh)return o===Ft?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===Oh)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===Fh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Bh||i===kh||i===Ja||i===zh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(i===Bh)return r.COMPRESSED_RED_RGTC1_EXT;if(i===kh)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===Ja)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===zh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Dr?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:t}}var nT=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,iT=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,Rf=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){let i=new Fa(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,i=new ns({vertexShader:nT,fragmentShader:iT,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new ts(new Ba(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Cf=class extends Fi{constructor(e,t){super();let i=this,s=null,r=1,o=null,a="local-floor",l=1,c=null,h=null,d=null,u=null,m=null,g=null,v=typeof XRWebGLBinding<"u",f=new Rf,p={},x=t.getContextAttributes(),A=null,b=null,C=[],w=[],_=new ut,M=null,U=null,L=new Kn;L.viewport=new sn;let R=new Kn;R.viewport=new sn;let z=[L,R],F=new eh,P=null,B=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(Q){let me=C[Q];return me===void 0&&(me=new Co,C[Q]=me),me.getTargetRaySpace()},this.getControllerGrip=function(Q){let me=C[Q];return me===void 0&&(me=new Co,C[Q]=me),me.getGripSpace()},this.getHand=function(Q){let me=C[Q];return me===void 0&&(me=new Co,C[Q]=me),me.getHandSpace()};function X(Q){let me=w.indexOf(Q.inputSource);if(me===-1)return;let fe=C[me];fe!==void 0&&(fe.update(Q.inputSource,Q.frame,c||o),fe.dispatchEvent({type:Q.type,data:Q.inputSource}))}function D(){s.removeEventListener("select",X),s.removeEventListener("selectstart",X),s.removeEventListener("selectend",X),s.removeEventListener("squeeze",X),s.removeEventListener("squeezestart",X),s.removeEventListener("squeezeend",X),s.removeEventListener("end",D),s.removeEventListener("inputsourceschange",ne);for(let Q=0;Q<C.length;Q++){let me=w[Q];me!==null&&(w[Q]=null,C[Q].disconnect(me))}P=null,B=null,f.reset();for(let Q in p)delete p[Q];if(e.setRenderTarget(A),m=null,u=null,d=null,s=null,b=null,le.stop(),i.isPresenting=!1,e.setPixelRatio(M),e.setSize(_.width,_.height,!1),U!==null){let Q=U.camera;Q.fov=U.fov,Q.zoom=U.zoom,Q.updateProjectionMatrix(),U=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(Q){r=Q,i.isPresenting===!0&&Ke("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(Q){a=Q,i.isPresenting===!0&&Ke("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||o},this.setReferenceSpace=function(Q){c=Q},this.getBaseLayer=function(){return u!==null?u:m},this.getBinding=function(){return d===null&&v&&(d=new XRWebGLBinding(s,t)),d},this.getFrame=function(){return g},this.getSession=function(){return s},this.setSession=async function(Q){if(s=Q,s!==null){if(A=e.getRenderTarget(),s.addEventListener("select",X),s.addEventListener("selectstart",X),s.addEventListener("selectend",X),s.addEventListener("squeeze",X),s.addEventListener("squeezestart",X),s.addEventListener("squeezeend",X),s.addEventListener("end",D),s.addEventListener("inputsourceschange",ne),x.xrCompatible!==!0&&await t.makeXRCompatible(),M=e.getPixelRatio(),e.getSize(_),v&&"createProjectionLayer"in XRWebGLBinding.prototype){let fe=null,ve=null,ye=null;x.depth&&(ye=x.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,fe=x.stencil?As:Ms,ve=x.stencil?Dr:Bi);let Ve={colorFormat:t.RGBA8,depthFormat:ye,scaleFactor:r};d=this.getBinding(),u=d.createProjectionLayer(Ve),s.updateRenderState({layers:[u]}),e.setPixelRatio(1),e.setSize(u.textureWidth,u.textureHeight,!1),b=new _i(u.textureWidth,u.textureHeight,{format:Gi,type:xi,depthTexture:new Es(u.textureWidth,u.textureHeight,ve,void 0,void 0,void 0,void 0,void 0,void 0,fe),stencilBuffer:x.stencil,colorSpace:e.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:u.ignoreDepthValues===!1,resolveStencilBuffer:u.ignoreDepthValues===!1,storeMultisampledDepthBuffer:u.ignoreDepthValues===!1,storeMultisampledStencilBuffer:u.ignoreDepthValues===!1})}else{let fe={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,fe),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),b=new _i(m.framebufferWidth,m.framebufferHeight,{format:Gi,type:xi,colorSpace:e.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}b.isXRRenderTarget=!0,this.setFoveation(l),c=null,o=await s.requestReferenceSpace(a),le.setContext(s),le.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return f.getDepthTexture()};function ne(Q){for(let me=0;me<Q.removed.length;me++){let fe=Q.removed[me],ve=w.indexOf(fe);ve>=0&&(w[ve]=null,C[ve].disconnect(fe))}for(let me=0;me<Q.added.length;me++){let fe=Q.added[me],ve=w.indexOf(fe);if(ve===-1){for(let Ve=0;Ve<C.length;Ve++)if(Ve>=w.length){w.push(fe),ve=Ve;break}else if(w[Ve]===null){w[Ve]=fe,ve=Ve;break}if(ve===-1)break}let ye=C[ve];ye&&ye.connect(fe)}}function q(Q,me){me===null?Q.matrixWorld.copy(Q.matrix):Q.matrixWorld.multiplyMatrices(me.matrixWorld,Q.matrix),Q.matrixWorldInverse.copy(Q.matrixWorld).invert()}this.updateCamera=function(Q){if(s===null)return;let me=Q.near,fe=Q.far;f.texture!==null&&(f.depthNear>0&&(me=f.depthNear),f.depthFar>0&&(fe=f.depthFar)),F.near=R.near=L.near=me,F.far=R.far=L.far=fe,(P!==F.near||B!==F.far)&&(s.updateRenderState({depthNear:F.near,depthFar:F.far}),P=F.near,B=F.far),F.layers.mask=Q.layers.mask|6,L.layers.mask=F.layers.mask&-5,R.layers.mask=F.layers.mask&-3;let ve=Q.parent,ye=F.cameras;q(F,ve);for(let Ve=0;Ve<ye.length;Ve++)q(ye[Ve],ve);F.projectionMatrix.copy(L.projectionMatrix),F.projectionMatrixInverse.copy(L.projectionMatrixInverse),U===null&&Q.isPerspectiveCamera&&(U={camera:Q,fov:Q.fov,zoom:Q.zoom}),W(Q,F,ve)};function W(Q,me,fe){fe===null?Q.matrix.copy(me.matrixWorld):(Q.matrix.copy(fe.matrixWorld),Q.matrix.invert(),Q.matrix.multiply(me.matrixWorld)),Q.matrix.decompose(Q.position,Q.quaternion,Q.scale),Q.updateMatrixWorld(!0),Q.projectionMatrix.copy(me.projectionMatrix),Q.projectionMatrixInverse.copy(me.projectionMatrixInverse),Q.isPerspectiveCamera&&(Q.fov=Ao*2*Math.atan(1/Q.projectionMatrix.elements[5]),Q.zoom=1)}this.getCamera=function(){return F},this.getFoveation=function(){if(!(u===null&&m===null))return l},this.setFoveation=function(Q){l=Q,u!==null&&(u.fixedFoveation=Q),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=Q)},this.hasDepthSensing=function(){return f.texture!==null},this.getDepthSensingMesh=function(){return f.getMesh(F)},this.getCameraTexture=function(Q){return p[Q]};let $=null;function re(Q,me){if(h=me.getViewerPose(c||o),g=me,h!==null){let fe=h.views;m!==null&&(e.setRenderTargetFramebuffer(b,m.framebuffer),e.setRenderTarget(b));let ve=!1;fe.length!==F.cameras.length&&(F.cameras.length=0,ve=!0);for(let Ne=0;Ne<fe.length;Ne++){let qe=fe[Ne],Qe=null;if(m!==null)Qe=m.getViewport(qe);else{let Xe=d.getViewSubImage(u,qe);Qe=Xe.viewport,Ne===0&&(e.setRenderTargetTextures(b,Xe.colorTexture,Xe.depthStencilTexture),e.setRenderTarget(b))}let pe=z[Ne];pe===void 0&&(pe=new Kn,pe.layers.enable(Ne),pe.viewport=new sn,z[Ne]=pe),pe.matrix.fromArray(qe.transform.matrix),pe.matrix.decompose(pe.position,pe.quaternion,pe.scale),pe.projectionMatrix.fromArray(qe.projectionMatrix),pe.projectionMatrixInverse.copy(pe.projectionMatrix).invert(),pe.viewport.set(Qe.x,Qe.y,Qe.width,Qe.height),Ne===0&&(F.matrix.copy(pe.matrix),F.matrix.decompose(F.position,F.quaternion,F.scale)),ve===!0&&F.cameras.push(pe)}let ye=s.enabledFeatures;if(ye&&ye.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&v){d=i.getBinding();let Ne=d.getDepthInformation(fe[0]);Ne&&Ne.isValid&&Ne.texture&&f.init(Ne,s.renderState)}if(ye&&ye.includes("camera-access")&&v){e.state.unbindTexture(),d=i.getBinding();for(let Ne=0;Ne<fe.length;Ne++){let qe=fe[Ne].camera;if(qe){let Qe=p[qe];Qe||(Qe=new Fa,p[qe]=Qe);let pe=d.getCameraImage(qe);Qe.sourceTexture=pe}}}}for(let fe=0;fe<C.length;fe++){let ve=w[fe],ye=C[fe];ve!==null&&ye!==void 0&&ye.update(ve,me,c||o)}$&&$(Q,me),me.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:me}),g=null}let le=new p_;le.setAnimationLoop(re),this.setAnimationLoop=function(Q){$=Q},this.dispose=function(){}}},sT=new en,w_=new at;w_.set(-1,0,0,0,1,0,0,0,1);function rT(n,e){function t(f,p){f.matrixAutoUpdate===!0&&f.updateMatrix(),p.value.copy(f.matrix)}function i(f,p){p.color.getRGB(f.fogColor.value,uf(n)),p.isFog?(f.fogNear.value=p.near,f.fogFar.value=p.far):p.isFogExp2&&(f.fogDensity.value=p.density)}function s(f,p,x,A,b){p.isNodeMaterial?p.uniformsNeedUpdate=!1:p.isMeshBasicMaterial?r(f,p):p.isMeshLambertMaterial?(r(f,p),p.envMap&&(f.envMapIntensity.value=p.envMapIntensity)):p.isMeshToonMaterial?(r(f,p),d(f,p)):p.isMeshPhongMaterial?(r(f,p),h(f,p),p.envMap&&(f.envMapIntensity.value=p.envMapIntensity)):p.isMeshStandardMaterial?(r(f,p),u(f,p),p.isMeshPhysicalMaterial&&m(f,p,b)):p.isMeshMatcapMaterial?(r(f,p),g(f,p)):p.isMeshDepthMaterial?r(f,p):p.isMeshDistanceMaterial?(r(f,p),v(f,p)):p.isMeshNormalMaterial?r(f,p):p.isLineBasicMaterial?(o(f,p),p.isLineDashedMaterial&&a(f,p)):p.isPointsMaterial?l(f,p,x,A):p.isSpriteMaterial?c(f,p):p.isShadowMaterial?(f.color.value.copy(p.color),f.opacity.value=p.opacity):p.isShaderMaterial&&(p.uniformsNeedUpdate=!1)}function r(f,p){f.opacity.value=p.opacity,p.color&&f.diffuse.value.copy(p.color),p.emissive&&f.emissive.value.copy(p.emissive).multiplyScalar(p.emissiveIntensity),p.map&&(f.map.value=p.map,t(p.map,f.mapTransform)),p.alphaMap&&(f.alphaMap.value=p.alphaMap,t(p.alphaMap,f.alphaMapTransform)),p.bumpMap&&(f.bumpMap.value=p.bumpMap,t(p.bumpMap,f.bumpMapTransform),f.bumpScale.value=p.bumpScale,p.side===jn&&(f.bumpScale.value*=-1)),p.normalMap&&(f.normalMap.value=p.normalMap,t(p.normalMap,f.normalMapTransform),f.normalScale.value.copy(p.normalScale),p.side===jn&&f.normalScale.value.negate()),p.displacementMap&&(f.displacementMap.value=p.displacementMap,t(p.displacementMap,f.displacementMapTransform),f.displacementScale.value=p.displacementScale,f.displacementBias.value=p.displacementBias),p.emissiveMap&&(f.emissiveMap.value=p.emissiveMap,t(p.emissiveMap,f.emissiveMapTransform)),p.specularMap&&(f.specularMap.value=p.specularMap,t(p.specularMap,f.specularMapTransform)),p.alphaTest>0&&(f.alphaTest.value=p.alphaTest);let x=e.get(p),A=x.envMap,b=x.envMapRotation;A&&(f.envMap.value=A,f.envMapRotation.value.setFromMatrix4(sT.makeRotationFromEuler(b)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&f.envMapRotation.value.premultiply(w_),f.reflectivity.value=p.reflectivity,f.ior.value=p.ior,f.refractionRatio.value=p.refractionRatio),p.lightMap&&(f.lightMap.value=p.lightMap,f.lightMapIntensity.value=p.lightMapIntensity,t(p.lightMap,f.lightMapTransform)),p.aoMap&&(f.aoMap.value=p.aoMap,f.aoMapIntensity.value=p.aoMapIntensity,t(p.aoMap,f.aoMapTransform))}function o(f,p){f.diffuse.value.copy(p.color),f.opacity.value=p.opacity,p.map&&(f.map.value=p.map,t(p.map,f.mapTransform))}function a(f,p){f.dashSize.value=p.dashSize,f.totalSize.value=p.dashSize+p.gapSize,f.scale.value=p.scale}function l(f,p,x,A){f.diffuse.value.copy(p.color),f.opacity.value=p.opacity,f.size.value=p.size*x,f.scale.value=A*.5,p.map&&(f.map.value=p.map,t(p.map,f.uvTransform)),p.alphaMap&&(f.alphaMap.value=p.alphaMap,t(p.alphaMap,f.alphaMapTransform)),p.alphaTest>0&&(f.alphaTest.value=p.alphaTest)}function c(f,p){f.diffuse.value.copy(p.color),f.opacity.value=p.opacity,f.rotation.value=p.rotation,p.map&&(f.map.value=p.map,t(p.map,f.mapTransform)),p.alphaMap&&(f.alphaMap.value=p.alphaMap,t(p.alphaMap,f.alphaMapTransform)),p.alphaTest>0&&(f.alphaTest.value=p.alphaTest)}function h(f,p){f.specular.value.copy(p.specular),f.shininess.value=Math.max(p.shininess,1e-4)}function d(f,p){p.gradientMap&&(f.gradientMap.value=p.gradientMap)}function u(f,p){f.metalness.value=p.metalness,p.metalnessMap&&(f.metalnessMap.value=p.metalnessMap,t(p.metalnessMap,f.metalnessMapTransform)),f.roughness.value=p.roughness,p.roughnessMap&&(f.roughnessMap.value=p.roughnessMap,t(p.roughnessMap,f.roughnessMapTransform)),p.envMap&&(f.envMapIntensity.value=p.envMapIntensity)}function m(f,p,x){f.ior.value=p.ior,p.diffuseRoughness>0&&(f.diffuseRoughness.value=p.diffuseRoughness,p.diffuseRoughnessMap&&(f.diffuseRoughnessMap.value=p.diffuseRoughnessMap,t(p.diffuseRoughnessMap,f.diffuseRoughnessMapTransform))),p.sheen>0&&(f.sheenColor.value.copy(p.sheenColor).multiplyScalar(p.sheen),f.sheenRoughness.value=p.sheenRoughness,p.sheenColorMap&&(f.sheenColorMap.value=p.sheenColorMap,t(p.sheenColorMap,f.sheenColorMapTransform)),p.sheenRoughnessMap&&(f.sheenRoughnessMap.value=p.sheenRoughnessMap,t(p.sheenRoughnessMap,f.sheenRoughnessMapTransform))),p.clearcoat>0&&(f.clearcoat.value=p.clearcoat,f.clearcoatRoughness.value=p.clearcoatRoughness,p.clearcoatMap&&(f.clearcoatMap.value=p.clearcoatMap,t(p.clearcoatMap,f.clearcoatMapTransform)),p.clearcoatRoughnessMap&&(f.clearcoatRoughnessMap.value=p.clearcoatRoughnessMap,t(p.clearcoatRoughnessMap,f.clearcoatRoughnessMapTransform)),p.clearcoatNormalMap&&(f.clearcoatNormalMap.value=p.clearcoatNormalMap,t(p.clearcoatNormalMap,f.clearcoatNormalMapTransform),f.clearcoatNormalScale.value.copy(p.clearcoatNormalScale),p.side===jn&&f.clearcoatNormalScale.value.negate())),p.dispersion>0&&(f.dispersion.value=p.dispersion),p.retroreflectivity>0&&(f.retroreflectivity.value=p.retroreflectivity),p.iridescence>0&&(f.iridescence.value=p.iridescence,f.iridescenceIOR.value=p.iridescenceIOR,f.iridescenceThicknessMinimum.value=p.iridescenceThicknessMinimum,f.iridescenceThicknessMaximum.value=p.iridescenceThicknessMaximum,p.iridescenceMap&&(f.iridescenceMap.value=p.iridescenceMap,t(p.iridescenceMap,f.iridescenceMapTransform)),p.iridescenceThicknessMap&&(f.iridescenceThicknessMap.value=p.iridescenceThicknessMap,t(p.iridescenceThicknessMap,f.iridescenceThicknessMapTransform))),p.transmission>0&&(f.transmission.value=p.transmission,f.transmissionSamplerMap.value=x.texture,f.transmissionSamplerSize.value.set(x.width,x.height),p.transmissionMap&&(f.transmissionMap.value=p.transmissionMap,t(p.transmissionMap,f.transmissionMapTransform)),f.thickness.value=p.thickness,p.thicknessMap&&(f.thicknessMap.value=p.thicknessMap,t(p.thicknessMap,f.thicknessMapTransform)),f.attenuationDistance.value=p.attenuationDistance,f.attenuationColor.value.copy(p.attenuationColor)),p.anisotropy>0&&(f.anisotropyVector.value.set(p.anisotropy*Math.cos(p.anisotropyRotation),p.anisotropy*Math.sin(p.anisotropyRotation)),p.anisotropyMap&&(f.anisotropyMap.value=p.anisotropyMap,t(p.anisotropyMap,f.anisotropyMapTransform))),f.specularIntensity.value=p.specularIntensity,f.specularColor.value.copy(p.specularColor),p.specularColorMap&&(f.specularColorMap.value=p.specularColorMap,t(p.specularColorMap,f.specularColorMapTransform)),p.specularIntensityMap&&(f.specularIntensityMap.value=p.specularIntensityMap,t(p.specularIntensityMap,f.specularIntensityMapTransform))}function g(f,p){p.matcap&&(f.matcap.value=p.matcap)}function v(f,p){let x=e.get(p).light;f.referencePosition.value.setFromMatrixPosition(x.matrixWorld),f.nearDistance.value=x.shadow.camera.near,f.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:s}}function oT(n,e,t,i){let s={},r={};function o(x,A){let b=A.program;i.uniformBlockBinding(x,b,s[x.id])}function a(x,A){let b=s[x.id];b===void 0&&(g(x),b=l(x),s[x.id]=b,x.addEventListener("dispose",f));let C=A.program;i.updateUBOMapping(x,C);let w=e.render.frame;r[x.id]!==w&&(c(x),r[x.id]=w)}function l(x){let A=n.createBuffer(),b=x.__size,C=x.usage;return n.bindBuffer(n.UNIFORM_BUFFER,A),n.bufferData(n.UNIFORM_BUFFER,b,C),n.bindBuffer(n.UNIFORM_BUFFER,null),A}function c(x){let A=s[x.id],b=x.uniforms,C=x.__cache;n.bindBuffer(n.UNIFORM_BUFFER,A);for(let w=0,_=b.length;w<_;w++){let M=b[w];if(Array.isArray(M))for(let U=0,L=M.length;U<L;U++)h(M[U],w,U,C);else h(M,w,0,C)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function h(x,A,b,C){if(u(x,A,b,C)===!0){let w=x.__offset,_=x.value;if(Array.isArray(_)){let M=0;for(let U=0;U<_.length;U++){let L=_[U],R=v(L,!0);d(L,x.__data,M),M+=R.storage/Float32Array.BYTES_PER_ELEMENT}}else d(_,x.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,w,x.__data)}}function d(x,A,b){typeof x=="number"||typeof x=="boolean"?A[b]=x:x.isMatrix3?(A[b]=x.elements[0],A[b+1]=x.elements[1],A[b+2]=x.elements[2],A[b+3]=0,A[b+4]=x.elements[3],A[b+5]=x.elements[4],A[b+6]=x.elements[5],A[b+7]=0,A[b+8]=x.elements[6],A[b+9]=x.elements[7],A[b+10]=x.elements[8],A[b+11]=0):ArrayBuffer.isView(x)?A.set(x.subarray(0,A.length-b),b):x.toArray(A,b)}function u(x,A,b,C){let w=x.value,_=A+"_"+b;if(Array.isArray(w)){C[_]===void 0&&(C[_]=[]);let M=C[_],U=!1;for(let L=0;L<w.length;L++)m(w[L],M,L)===!0&&(U=!0);return U}return m(w,C,_)}function m(x,A,b){if(A[b]===void 0)return typeof x=="number"||typeof x=="boolean"?A[b]=x:ArrayBuffer.isView(x)?A[b]=x.slice():A[b]=x.clone(),!0;{let C=A[b];if(typeof x=="number"||typeof x=="boolean"){if(C!==x)return A[b]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(C.equals(x)===!1)return C.copy(x),!0}}return!1}function g(x){let A=x.uniforms,b=0,C=16;for(let _=0,M=A.length;_<M;_++){let U=Array.isArray(A[_])?A[_]:[A[_]];for(let L=0,R=U.length;L<R;L++){let z=U[L],F=Array.isArray(z.value)?z.value:[z.value],P=Array.isArray(A[_])||Array.isArray(z.value),B=b;for(let D=0,ne=F.length;D<ne;D++){let q=F[D],W=v(q,P),$=b%C,re=$%W.boundary,le=$+re;b+=re,le!==0&&C-le<W.storage&&(b+=C-le),D===0&&(B=b),b+=W.storage}let X=z.type==="int"?Int32Array:z.type==="uint"?Uint32Array:Float32Array;z.__data=new X((b-B)/Float32Array.BYTES_PER_ELEMENT),z.__offset=B}}let w=b%C;return w>0&&(b+=C-w),x.__size=b,x.__cache={},this}function v(x,A){let b={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(b.boundary=4,b.storage=4):x.isVector2?(b.boundary=8,b.storage=8):x.isVector3||x.isColor?(b.boundary=16,b.storage=12):x.isVector4?(b.boundary=16,b.storage=16):x.isMatrix3?(b.boundary=16,b.storage=48):x.isMatrix4?(b.boundary=16,b.storage=64):x.isTexture?Ke("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(b.boundary=16,b.storage=x.byteLength):Ke("WebGLRenderer: Unsupported uniform value type.",x),A===!0&&(b.boundary=16,b.storage=Math.ceil(b.storage/16)*16),b}function f(x){let A=x.target;A.removeEventListener("dispose",f),n.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function p(){for(let x in s)n.deleteBuffer(s[x]);s={},r={}}return{bind:o,update:a,dispose:p}}var aT=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),rs=null;function lT(){return rs===null&&(rs=new Uc(aT,16,16,lr,zi),rs.name="DFG_LUT",rs.minFilter=Jn,rs.magFilter=Jn,rs.wrapS=es,rs.wrapT=es,rs.generateMipmaps=!1,rs.needsUpdate=!0),rs}var Wh=class{constructor(e={}){let{canvas:t=F0(),context:i=null,depth:s=!0,stencil:r=!1,alpha:o=!1,antialias:a=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:d=!1,reversedDepthBuffer:u=!1,outputBufferType:m=xi}=e;this.isWebGLRenderer=!0;let g;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");g=i.getContextAttributes().alpha}else g=o;let v=m,f=new Set([hh,ch,lh]),p=new Set([xi,Bi,Bo,Dr,oh,ah]),x=new Uint32Array(4),A=new Int32Array(4),b={textures:[],min:[],max:[],resolution:[]},C=null,w=null,_=[],M=[],U=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ss,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let L=this,R=!1,z=null,F=null,P=null,B=null;this._outputColorSpace=fi;let X=0,D=0,ne=null,q=-1,W=null,$=new sn,re=new sn,le=null,Q=new gt(0),me=0,fe=t.width,ve=t.height,ye=1,Ve=null,Je=null,Ne=new sn(0,0,fe,ve),qe=new sn(0,0,fe,ve),Qe=!1,pe=new Ir,Xe=new Oc,et=!1,Gt=!1,Rt=new en,cn=new J,dt=new sn,Pt={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},At=!1;function pt(){return ne===null?ye:1}let k=i;function be(T,H){return t.getContext(T,H)}let je,ht,Ae,Vt,We,Ze,I,S,Y,de,ce,Me,we,ie,oe,_e,G,ae,se,Re,Se,Te,$e;try{let T={alpha:!0,depth:s,stencil:r,antialias:a,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:d};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${"187"}`),t.addEventListener("webglcontextlost",ze,!1),t.addEventListener("webglcontextrestored",st,!1),t.addEventListener("webglcontextcreationerror",Pe,!1),k===null){let H="webgl2";if(k=be(H,T),k===null)throw be(H)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}it()}catch(T){throw t.removeEventListener("webglcontextlost",ze,!1),t.removeEventListener("webglcontextrestored",st,!1),t.removeEventListener("webglcontextcreationerror",Pe,!1),ot("WebGLRenderer: "+T.message),T}function it(){je=new xw(k),je.init(),Se=new tT(k,je),ht=new lw(k,je,e,Se),Ae=new QE(k,je),ht.reversedDepthBuffer&&u&&Ae.buffers.depth.setReversed(!0),F=k.createFramebuffer(),P=k.createFramebuffer(),B=k.createFramebuffer(),Vt=new Sw(k),We=new kE,Ze=new eT(k,je,Ae,We,ht,Se,Vt),I=new yw(L),S=new wb(k),Te=new ow(k,S),Y=new vw(k,S,Vt,Te),de=new ww(k,Y,S,Te,Vt),ae=new Mw(k,ht,Ze),oe=new cw(We),ce=new BE(L,I,je,ht,Te,oe),Me=new rT(L,We),we=new GE,ie=new qE(je),G=new rw(L,I,Ae,de,g,l),_e=new jE(L,de,ht),$e=new oT(k,Vt,ht,Ae),se=new aw(k,je,Vt),Re=new bw(k,je,Vt),Vt.programs=ce.programs,L.capabilities=ht,L.extensions=je,L.properties=We,L.renderLists=we,L.shadowMap=_e,L.state=Ae,L.info=Vt}v!==xi&&(U=new Tw(v,t.width,t.height,a,s,r));let ue=new Cf(L,k);this.xr=ue,this.getContext=function(){return k},this.getContextAttributes=function(){return k.getContextAttributes()},this.forceContextLoss=function(){let T=je.get("WEBGL_lose_context");T&&T.loseContext()},this.forceContextRestore=function(){let T=je.get("WEBGL_lose_context");T&&T.restoreContext()},this.getPixelRatio=function(){return ye},this.setPixelRatio=function(T){T!==void 0&&(ye=T,this.setSize(fe,ve,!1))},this.getSize=function(T){return T.set(fe,ve)},this.setSize=function(T,H,ee=!0){if(ue.isPresenting){Ke("WebGLRenderer: Can't change size while VR device is presenting.");return}fe=T,ve=H,t.width=Math.floor(T*ye),t.height=Math.floor(H*ye),ee===!0&&(t.style.width=T+"px",t.style.height=H+"px"),U!==null&&U.setSize(t.width,t.height),this.setViewport(0,0,T,H)},this.getDrawingBufferSize=function(T){return T.set(fe*ye,ve*ye).floor()},this.setDrawingBufferSize=function(T,H,ee){fe=T,ve=H,ye=ee,t.width=Math.floor(T*ee),t.height=Math.floor(H*ee),this.setViewport(0,0,T,H)},this.setEffects=function(T){if(v===xi){ot("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(T){for(let H=0;H<T.length;H++)if(T[H].isOutputPass===!0){Ke("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}U.setEffects(T||[])},this.getCurrentViewport=function(T){return T.copy($)},this.getViewport=function(T){return T.copy(Ne)},this.setViewport=function(T,H,ee,Z){T.isVector4?Ne.set(T.x,T.y,T.z,T.w):Ne.set(T,H,ee,Z),Ae.viewport($.copy(Ne).multiplyScalar(pt()).round())},this.getScissor=function(T){return T.copy(qe)},this.setScissor=function(T,H,ee,Z){T.isVector4?qe.set(T.x,T.y,T.z,T.w):qe.set(T,H,ee,Z),Ae.scissor(re.copy(qe).multiplyScalar(pt()).round())},this.getScissorTest=function(){return Qe},this.setScissorTest=function(T){Ae.setScissorTest(Qe=T)},this.setOpaqueSort=function(T){Ve=T},this.setTransparentSort=function(T){Je=T},this.getClearColor=function(T){return T.copy(G.getClearColor())},this.setClearColor=function(){G.setClearColor(...arguments)},this.getClearAlpha=function(){return G.getClearAlpha()},this.setClearAlpha=function(){G.setClearAlpha(...arguments)},this.clear=function(T=!0,H=!0,ee=!0){let Z=0;if(T){let K=!1;if(ne!==null){let Ce=ne.texture.format;K=f.has(Ce)}if(K){let Ce=ne.texture.type,Le=p.has(Ce),Ie=G.getClearColor(),De=G.getClearAlpha(),He=Ie.r,rt=Ie.g,yt=Ie.b;Le?(x[0]=He,x[1]=rt,x[2]=yt,x[3]=De,k.clearBufferuiv(k.COLOR,0,x)):(A[0]=He,A[1]=rt,A[2]=yt,A[3]=De,k.clearBufferiv(k.COLOR,0,A))}else Z|=k.COLOR_BUFFER_BIT}H&&(Z|=k.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),ee&&(Z|=k.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),Z!==0&&k.clear(Z)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(T){T.setRenderer(this),z=T},this.dispose=function(){t.removeEventListener("webglcontextlost",ze,!1),t.removeEventListener("webglcontextrestored",st,!1),t.removeEventListener("webglcontextcreationerror",Pe,!1),G.dispose(),we.dispose(),ie.dispose(),Ze.dispose(),We.dispose(),I.dispose(),de.dispose(),Y.dispose(),Te.dispose(),$e.dispose(),ce.dispose(),ue.dispose(),ue.removeEventListener("sessionstart",sl),ue.removeEventListener("sessionend",Vi),as.stop()};function ze(T){T.preventDefault(),of("WebGLRenderer: Context Lost."),R=!0}function st(){of("WebGLRenderer: Context Restored."),R=!1;let T=Vt.autoReset,H=_e.enabled,ee=_e.autoUpdate,Z=_e.needsUpdate,K=_e.type;it(),Vt.autoReset=T,_e.enabled=H,_e.autoUpdate=ee,_e.needsUpdate=Z,_e.type=K}function Pe(T){ot("WebGLRenderer: A WebGL context could not be created. Reason: ",T.statusMessage)}function ft(T){let H=T.target;H.removeEventListener("dispose",ft),$t(H)}function $t(T){Wn(T),We.remove(T)}function Wn(T){let H=We.get(T).programs;H!==void 0&&(H.forEach(function(ee){ce.releaseProgram(ee)}),T.isShaderMaterial&&ce.releaseShaderCache(T))}this.renderBufferDirect=function(T,H,ee,Z,K,Ce){H===null&&(H=Pt);let Le=K.isMesh&&K.matrixWorld.determinantAffine()<0,Ie=Xo(T,H,ee,Z,K);Ae.setMaterial(Z,Le);let De=ee.index,He=1;if(Z.wireframe===!0){if(De=Y.getWireframeAttribute(ee),De===void 0)return;He=2}let rt=ee.drawRange,yt=ee.attributes.position,Ge=rt.start*He,xt=(rt.start+rt.count)*He;Ce!==null&&(Ge=Math.max(Ge,Ce.start*He),xt=Math.min(xt,(Ce.start+Ce.count)*He)),De!==null?(Ge=Math.max(Ge,0),xt=Math.min(xt,De.count)):yt!=null&&(Ge=Math.max(Ge,0),xt=Math.min(xt,yt.count));let tn=xt-Ge;if(tn<0||tn===1/0)return;Te.setup(K,Z,Ie,ee,De);let Bt,kt=se;if(De!==null&&(Bt=S.get(De),kt=Re,kt.setIndex(Bt)),K.isMesh)Z.wireframe===!0?(Ae.setLineWidth(Z.wireframeLinewidth*pt()),kt.setMode(k.LINES)):kt.setMode(k.TRIANGLES);else if(K.isLine){let vn=Z.linewidth;vn===void 0&&(vn=1),Ae.setLineWidth(vn*pt()),K.isLineSegments?kt.setMode(k.LINES):K.isLineLoop?kt.setMode(k.LINE_LOOP):kt.setMode(k.LINE_STRIP)}else K.isPoints?kt.setMode(k.POINTS):K.isSprite&&kt.setMode(k.TRIANGLES);if(K.isBatchedMesh)if(je.get("WEBGL_multi_draw"))kt.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{let vn=K._multiDrawStarts,Be=K._multiDrawCounts,dn=K._multiDrawCount,wt=De?S.get(De).bytesPerElement:1,cs=We.get(Z).currentProgram.getUniforms();for(let fn=0;fn<dn;fn++)cs.setValue(k,"_gl_DrawID",fn),kt.render(vn[fn]/wt,Be[fn])}else if(K.isInstancedMesh)kt.renderInstances(Ge,tn,K.count);else if(ee.isInstancedBufferGeometry){let vn=ee._maxInstanceCount!==void 0?ee._maxInstanceCount:1/0,Be=Math.min(ee.instanceCount,vn);kt.renderInstances(Ge,tn,Be)}else kt.render(Ge,tn)};function Ho(T,H,ee,Z){z!==null&&T.isNodeMaterial&&z.setObject(Z,T),et===!0&&oe.setState(T,ee,!1),T.transparent===!0&&T.side===is&&T.forceSinglePass===!1?(T.side=jn,T.needsUpdate=!0,Wi(T,H,Z),T.side=ar,T.needsUpdate=!0,Wi(T,H,Z),T.side=is):Wi(T,H,Z)}this.compile=function(T,H,ee=null){ee===null&&(ee=T),z!==null&&z.renderStart(T,H,ee),w=ie.get(ee),w.init(H),M.push(w),ee.traverseVisible(function(K){K.isLight&&K.layers.test(H.layers)&&(w.pushLight(K),K.castShadow&&w.pushShadow(K))}),T!==ee&&T.traverseVisible(function(K){K.isLight&&K.layers.test(H.layers)&&(w.pushLight(K),K.castShadow&&w.pushShadow(K))}),w.setupLights(),z!==null&&z.updateLights(w.state.lightsArray),Gt=this.localClippingEnabled,et=oe.init(this.clippingPlanes,Gt),et===!0&&oe.setGlobalState(this.clippingPlanes,H),z!==null&&_e.render(w.state.shadowsArray,ee,H);let Z=new Set;return T.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;let Ce=K.material;if(Ce)if(Array.isArray(Ce))for(let Le=0;Le<Ce.length;Le++){let Ie=Ce[Le];Ho(Ie,ee,H,K),Z.add(Ie)}else Ho(Ce,ee,H,K),Z.add(Ce)}),w=M.pop(),z!==null&&z.renderEnd(),Z},this.compileAsync=function(T,H,ee=null){let Z=this.compile(T,H,ee);return new Promise(K=>{function Ce(){if(Z.forEach(function(Le){let De=We.get(Le).currentProgram;(De===void 0||De.isReady())&&Z.delete(Le)}),Z.size===0){K(T);return}setTimeout(Ce,10)}je.get("KHR_parallel_shader_compile")!==null?Ce():setTimeout(Ce,10)})};let Fr=null;function jh(T){Fr&&Fr(T)}function sl(){as.stop()}function Vi(){as.start()}let as=new p_;as.setAnimationLoop(jh),typeof self<"u"&&as.setContext(self),this.setAnimationLoop=function(T){Fr=T,ue.setAnimationLoop(T),T===null?as.stop():as.start()},ue.addEventListener("sessionstart",sl),ue.addEventListener("sessionend",Vi),this.render=function(T,H){if(H!==void 0&&H.isCamera!==!0){ot("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(R===!0)return;z!==null&&z.renderStart(T,H);let ee=ue.enabled===!0&&ue.isPresenting===!0,Z=U!==null&&(ne===null||ee)&&U.begin(L,ne);if(T.matrixWorldAutoUpdate===!0&&T.updateMatrixWorld(),H.parent===null&&H.matrixWorldAutoUpdate===!0&&H.updateMatrixWorld(),ue.enabled===!0&&ue.isPresenting===!0&&(U===null||U.isCompositing()===!1)&&(ue.cameraAutoUpdate===!0&&ue.updateCamera(H),H=ue.getCamera()),T.isScene===!0&&T.onBeforeRender(L,T,H,ne),w=ie.get(T,M.length),w.init(H),w.state.textureUnits=Ze.getTextureUnits(),M.push(w),Rt.multiplyMatrices(H.projectionMatrix,H.matrixWorldInverse),H.isArrayCamera?Xe.setFromArrayCamera(H):pe.setFromProjectionMatrix(Rt,Ti,H.reversedDepth),Gt=this.localClippingEnabled,et=oe.init(this.clippingPlanes,Gt),C=we.get(T,_.length),C.init(),_.push(C),this.info.render.frame++,ue.enabled===!0&&ue.isPresenting===!0){let Le=L.xr.getDepthSensingMesh();Le!==null&&ls(Le,H,-1/0,L.sortObjects)}ls(T,H,0,L.sortObjects),C.finish(),z!==null&&z.updateLights(w.state.lightsArray),L.sortObjects===!0&&C.sort(Ve,Je),At=ue.enabled===!1||ue.isPresenting===!1||ue.hasDepthSensing()===!1,At&&G.addToRenderList(C,T),this.info.autoReset===!0&&this.info.reset(),et===!0&&oe.beginShadows();let K=w.state.shadowsArray;if(_e.render(K,T,H),et===!0&&oe.endShadows(),(Z&&U.hasRenderPass())===!1){let Le=C.opaque,Ie=C.transmissive;if(w.setupLights(),H.isArrayCamera){let De=H.cameras;if(Ie.length>0)for(let He=0,rt=De.length;He<rt;He++){let yt=De[He];Ai(Le,Ie,T,yt)}At&&G.render(T);for(let He=0,rt=De.length;He<rt;He++){let yt=De[He];Vo(C,T,yt,yt.viewport)}}else Ie.length>0&&Ai(Le,Ie,T,H),At&&G.render(T),Vo(C,T,H)}ne!==null&&D===0&&(Ze.updateMultisampleRenderTarget(ne),Ze.updateRenderTargetMipmap(ne)),Z&&U.end(L),T.isScene===!0&&T.onAfterRender(L,T,H),Te.resetDefaultState(),q=-1,W=null,M.pop(),M.length>0?(w=M[M.length-1],Ze.setTextureUnits(w.state.textureUnits),et===!0&&oe.setGlobalState(L.clippingPlanes,w.state.camera)):w=null,_.pop(),_.length>0?C=_[_.length-1]:C=null,z!==null&&z.renderEnd()};function ls(T,H,ee,Z){if(T.visible===!1)return;if(T.layers.test(H.layers)){if(T.isGroup)ee=T.renderOrder;else if(T.isLOD)T.autoUpdate===!0&&T.update(H);else if(T.isLight)w.pushLight(T),T.castShadow&&w.pushShadow(T);else if(T.isSprite){let Le=H.isArrayCamera?Xe:pe;if(!T.frustumCulled||T.intersectsFrustum(Le)){Z&&dt.setFromMatrixPosition(T.matrixWorld).applyMatrix4(Rt);let Ie=de.update(T),De=T.material;De.visible&&C.push(T,Ie,De,ee,dt.z,null,H)}}else if(T.isMesh||T.isLine||T.isPoints){let Le=H.isArrayCamera?Xe:pe;if(!T.frustumCulled||T.intersectsFrustum(Le)){let Ie=de.update(T),De=T.material;if(Z&&(T.boundingSphere!==void 0?(T.boundingSphere===null&&T.computeBoundingSphere(),dt.copy(T.boundingSphere.center)):(Ie.boundingSphere===null&&Ie.computeBoundingSphere(),dt.copy(Ie.boundingSphere.center)),dt.applyMatrix4(T.matrixWorld).applyMatrix4(Rt)),Array.isArray(De)){let He=Ie.groups;for(let rt=0,yt=He.length;rt<yt;rt++){let Ge=He[rt],xt=De[Ge.materialIndex];xt&&xt.visible&&C.push(T,Ie,xt,ee,dt.z,Ge,H)}}else De.visible&&C.push(T,Ie,De,ee,dt.z,null,H)}}}let Ce=T.children;for(let Le=0,Ie=Ce.length;Le<Ie;Le++)ls(Ce[Le],H,ee,Z)}function Vo(T,H,ee,Z){let{opaque:K,transmissive:Ce,transparent:Le}=T;w.setupLightsView(ee),et===!0&&oe.setGlobalState(L.clippingPlanes,ee),Z&&Ae.viewport($.copy(Z)),K.length>0&&rn(K,H,ee),Ce.length>0&&rn(Ce,H,ee),Le.length>0&&rn(Le,H,ee),Ae.buffers.depth.setTest(!0),Ae.buffers.depth.setMask(!0),Ae.buffers.color.setMask(!0),Ae.setPolygonOffset(!1)}function Ai(T,H,ee,Z){if((ee.isScene===!0?ee.overrideMaterial:null)!==null)return;if(w.state.transmissionRenderTarget[Z.id]===void 0){let Ge=je.has("EXT_color_buffer_half_float")||je.has("EXT_color_buffer_float");w.state.transmissionRenderTarget[Z.id]=new _i(1,1,{generateMipmaps:!0,type:Ge?zi:xi,minFilter:Ts,samples:Math.max(4,ht.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:Tt.workingColorSpace})}let Ce=w.state.transmissionRenderTarget[Z.id],Le=Z.viewport||$;Ce.setSize(Le.z*L.transmissionResolutionScale,Le.w*L.transmissionResolutionScale);let Ie=L.getRenderTarget(),De=L.getActiveCubeFace(),He=L.getActiveMipmapLevel();L.setRenderTarget(Ce),L.getClearColor(Q),me=L.getClearAlpha(),me<1&&L.setClearColor(16777215,.5),L.clear(),At&&G.render(ee);let rt=L.toneMapping;L.toneMapping=ss;let yt=Z.viewport;if(Z.viewport!==void 0&&(Z.viewport=void 0),w.setupLightsView(Z),et===!0&&oe.setGlobalState(L.clippingPlanes,Z),rn(T,ee,Z),Ze.updateMultisampleRenderTarget(Ce),Ze.updateRenderTargetMipmap(Ce),je.has("WEBGL_multisampled_render_to_texture")===!1){let Ge=!1;for(let xt=0,tn=H.length;xt<tn;xt++){let Bt=H[xt],{object:kt,geometry:vn,material:Be,group:dn}=Bt;if(Be.side===is&&kt.layers.test(Z.layers)){let wt=Be.side;Be.side=jn,Be.needsUpdate=!0,hn(kt,ee,Z,vn,Be,dn),Be.side=wt,Be.needsUpdate=!0,Ge=!0}}Ge===!0&&(Ze.updateMultisampleRenderTarget(Ce),Ze.updateRenderTargetMipmap(Ce))}L.setRenderTarget(Ie,De,He),L.setClearColor(Q,me),yt!==void 0&&(Z.viewport=yt),L.toneMapping=rt}function rn(T,H,ee){let Z=H.isScene===!0?H.overrideMaterial:null;for(let K=0,Ce=T.length;K<Ce;K++){let Le=T[K],{object:Ie,geometry:De,group:He}=Le,rt=Le.material;rt.allowOverride===!0&&Z!==null&&(rt=Z),Ie.layers.test(ee.layers)&&hn(Ie,H,ee,De,rt,He)}}function hn(T,H,ee,Z,K,Ce){z!==null&&K.isNodeMaterial&&z.setObject(T,K),T.onBeforeRender(L,H,ee,Z,K,Ce),T.modelViewMatrix.multiplyMatrices(ee.matrixWorldInverse,T.matrixWorld),T.normalMatrix.getNormalMatrix(T.modelViewMatrix),K.onBeforeRender(L,H,ee,Z,T,Ce),K.transparent===!0&&K.side===is&&K.forceSinglePass===!1?(K.side=jn,K.needsUpdate=!0,L.renderBufferDirect(ee,H,Z,K,T,Ce),K.side=ar,K.needsUpdate=!0,L.renderBufferDirect(ee,H,Z,K,T,Ce),K.side=is):L.renderBufferDirect(ee,H,Z,K,T,Ce),T.onAfterRender(L,H,ee,Z,K,Ce)}function un(T){let H=0;for(let ee of T)ee.texture!==null&&H++;return H}function Wi(T,H,ee){H.isScene!==!0&&(H=Pt);let Z=We.get(T),K=w.state.lights,Ce=w.state.shadowsArray,Le=K.state.version,Ie=ce.getParameters(T,K.state,Ce,H,ee,w.state.lightProbeGridArray),De=ce.getProgramCacheKey(Ie),He=Z.programs;Z.environment=T.isMeshStandardMaterial||T.isMeshLambertMaterial||T.isMeshPhongMaterial?H.environment:null,Z.fog=H.fog;let rt=T.isMeshStandardMaterial||T.isMeshLambertMaterial&&!T.envMap||T.isMeshPhongMaterial&&!T.envMap;Z.envMap=I.get(T.envMap||Z.environment,rt),Z.envMapRotation=Z.environment!==null&&T.envMap===null?H.environmentRotation:T.envMapRotation,He===void 0&&(T.addEventListener("dispose",ft),He=new Map,Z.programs=He,Z.programVariants=new Map);let yt=He.get(De);if(yt!==void 0){if(Z.currentProgram===yt&&Z.lightsStateVersion===Le)return Wo(T,Ie),yt}else Ie.uniforms=ce.getUniforms(T),z!==null&&T.isNodeMaterial&&z.build(T,ee,Ie),T.onBeforeCompile(Ie,L),yt=ce.acquireProgram(Ie,De),He.set(De,yt),Z.uniforms=Ie.uniforms;let Ge=Z.uniforms;return(!T.isShaderMaterial&&!T.isRawShaderMaterial||T.clipping===!0)&&(Ge.clippingPlanes=oe.uniform),Wo(T,Ie),Z.needsLights=Ps(T),Z.lightsStateVersion=Le,Z.needsLights&&(Ge.ambientLightColor.value=K.state.ambient,Ge.lightProbe.value=K.state.probe,Ge.sunLights.value=K.state.sun,Ge.sunLightShadows.value=K.state.sunShadow,Ge.directionalLights.value=K.state.directional,Ge.directionalLightShadows.value=K.state.directionalShadow,Ge.spotLights.value=K.state.spot,Ge.spotLightShadows.value=K.state.spotShadow,Ge.rectAreaLights.value=K.state.rectArea,Ge.ltc_1.value=K.state.rectAreaLTC1,Ge.ltc_2.value=K.state.rectAreaLTC2,Ge.pointLights.value=K.state.point,Ge.pointLightShadows.value=K.state.pointShadow,Ge.hemisphereLights.value=K.state.hemi,Ge.sunShadowMatrix.value=K.state.sunShadowMatrix,Ge.sunShadowCascade.value=K.state.sunShadowCascade,Ge.directionalShadowMatrix.value=K.state.directionalShadowMatrix,Ge.spotLightMatrix.value=K.state.spotLightMatrix,Ge.spotLightMap.value=K.state.spotLightMap,Ge.pointShadowMatrix.value=K.state.pointShadowMatrix),Z.numLightProbeGrids=un(w.state.lightProbeGridArray),Z.currentProgram=yt,Z.uniformsList=null,yt}function si(T,H,ee,Z,K){let Ce=We.get(T),Le=Ce.currentProgram.id+","+Z+","+K,Ie=Ce.programVariants.get(Le);return Ie===void 0?(Ie=Wi(T,H,ee),Ce.programVariants.set(Le,Ie)):(Ce.currentProgram=Ie,Ce.uniformsList=null,Ce.outputColorSpace=Z,Ce.toneMapping=K),Ie}function Is(T){if(T.uniformsList===null){let H=T.currentProgram.getUniforms();T.uniformsList=zo.seqWithValue(H.seq,T.uniforms)}return T.uniformsList}function Wo(T,H){let ee=We.get(T);ee.outputColorSpace=H.outputColorSpace,ee.batching=H.batching,ee.batchingColor=H.batchingColor,ee.instancing=H.instancing,ee.instancingColor=H.instancingColor,ee.instancingMorph=H.instancingMorph,ee.skinning=H.skinning,ee.morphTargets=H.morphTargets,ee.morphNormals=H.morphNormals,ee.morphColors=H.morphColors,ee.morphTargetsCount=H.morphTargetsCount,ee.numClippingPlanes=H.numClippingPlanes,ee.numIntersection=H.numClipIntersection,ee.vertexAlphas=H.vertexAlphas,ee.vertexTangents=H.vertexTangents,ee.toneMapping=H.toneMapping}function Xo(T,H,ee,Z,K){H.isScene!==!0&&(H=Pt),Ze.resetTextureUnits();let Ce=H.fog,Le=Z.isMeshStandardMaterial||Z.isMeshLambertMaterial||Z.isMeshPhongMaterial?H.environment:null,Ie=ne===null?L.outputColorSpace:ne.isXRRenderTarget===!0?ne.texture.colorSpace:Tt.workingColorSpace,De=Z.isMeshStandardMaterial||Z.isMeshLambertMaterial&&!Z.envMap||Z.isMeshPhongMaterial&&!Z.envMap,He=I.get(Z.envMap||Le,De),rt=Z.vertexColors===!0&&!!ee.attributes.color&&ee.attributes.color.itemSize===4,yt=!!ee.attributes.tangent&&(!!Z.normalMap||Z.anisotropy>0),Ge=!!ee.morphAttributes.position,xt=!!ee.morphAttributes.normal,tn=!!ee.morphAttributes.color,Bt=ss;Z.toneMapped&&(ne===null||ne.isXRRenderTarget===!0)&&(Bt=L.toneMapping);let kt=ee.morphAttributes.position||ee.morphAttributes.normal||ee.morphAttributes.color,vn=kt!==void 0?kt.length:0,Be=We.get(Z),dn=w.state.lights;if(et===!0&&(Gt===!0||T!==W)){let zt=T===W&&Z.id===q;oe.setState(Z,T,zt)}let wt=!1,cs=!1;Z.version===Be.__version?Be.needsLights&&Be.lightsStateVersion!==dn.state.version||K.isBatchedMesh&&Be.batching===!1||!K.isBatchedMesh&&Be.batching===!0||K.isBatchedMesh&&Be.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&Be.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&Be.instancing===!1||!K.isInstancedMesh&&Be.instancing===!0||K.isSkinnedMesh&&Be.skinning===!1||!K.isSkinnedMesh&&Be.skinning===!0||K.isInstancedMesh&&Be.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&Be.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&Be.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&Be.instancingMorph===!1&&K.morphTexture!==null||Be.envMap!==He||Z.fog===!0&&Be.fog!==Ce||Be.numClippingPlanes!==void 0&&(Be.numClippingPlanes!==oe.numPlanes||Be.numIntersection!==oe.numIntersection)||Be.vertexAlphas!==rt||Be.vertexTangents!==yt||Be.morphTargets!==Ge||Be.morphNormals!==xt||Be.morphColors!==tn||Be.morphTargetsCount!==vn||Be.numLightProbeGrids!==un(w.state.lightProbeGridArray)?wt=!0:(Be.outputColorSpace!==Ie||Be.toneMapping!==Bt)&&(cs=!0):(wt=!0,Be.__version=Z.version);let fn=Be.currentProgram;(wt===!0||cs===!0)&&(fn=cs===!0?si(Z,H,K,Ie,Bt):Wi(Z,H,K),z&&Z.isNodeMaterial&&z.onUpdateProgram(Z,fn,Be));let zr=!1,Xi=!1,hs=!1,mt=fn.getUniforms(),on=Be.uniforms;if(Ae.useProgram(fn.program)&&(zr=!0,Xi=!0,hs=!0),Z.id!==q&&(q=Z.id,Xi=!0),zr||W!==T){Ae.buffers.depth.getReversed()&&T.reversedDepth!==!0&&(T._reversedDepth=!0,T.updateProjectionMatrix()),mt.setValue(k,"projectionMatrix",T.projectionMatrix),mt.setValue(k,"viewMatrix",T.matrixWorldInverse);let pn=mt.map.cameraPosition;pn!==void 0&&pn.setValue(k,cn.setFromMatrixPosition(T.matrixWorld)),ht.logarithmicDepthBuffer&&mt.setValue(k,"logDepthBufFC",2/(Math.log(T.far+1)/Math.LN2)),(Z.isMeshPhongMaterial||Z.isMeshToonMaterial||Z.isMeshLambertMaterial||Z.isMeshBasicMaterial||Z.isMeshStandardMaterial||Z.isShaderMaterial)&&mt.setValue(k,"isOrthographic",T.isOrthographicCamera===!0),W!==T&&(W=T,Xi=!0,hs=!0)}if(Be.needsLights&&(dn.state.sunShadowMap.length>0&&mt.setValue(k,"sunShadowMap",dn.state.sunShadowMap,Ze),dn.state.directionalShadowMap.length>0&&mt.setValue(k,"directionalShadowMap",dn.state.directionalShadowMap,Ze),dn.state.spotShadowMap.length>0&&mt.setValue(k,"spotShadowMap",dn.state.spotShadowMap,Ze),dn.state.pointShadowMap.length>0&&mt.setValue(k,"pointShadowMap",dn.state.pointShadowMap,Ze)),K.isSkinnedMesh){mt.setOptional(k,K,"bindMatrix"),mt.setOptional(k,K,"bindMatrixInverse");let zt=K.skeleton;zt&&(zt.boneTexture===null&&zt.computeBoneTexture(),mt.setValue(k,"boneTexture",zt.boneTexture,Ze))}K.isBatchedMesh&&(mt.setOptional(k,K,"batchingTexture"),mt.setValue(k,"batchingTexture",K._matricesTexture,Ze),mt.setOptional(k,K,"batchingIdTexture"),mt.setValue(k,"batchingIdTexture",K._indirectTexture,Ze),mt.setOptional(k,K,"batchingColorTexture"),K._colorsTexture!==null&&mt.setValue(k,"batchingColorTexture",K._colorsTexture,Ze));let Xn=ee.morphAttributes;if((Xn.position!==void 0||Xn.normal!==void 0||Xn.color!==void 0)&&ae.update(K,ee,fn),(Xi||Be.receiveShadow!==K.receiveShadow)&&(Be.receiveShadow=K.receiveShadow,mt.setValue(k,"receiveShadow",K.receiveShadow)),(Z.isMeshStandardMaterial||Z.isMeshLambertMaterial||Z.isMeshPhongMaterial)&&Z.envMap===null&&H.environment!==null&&(on.envMapIntensity.value=H.environmentIntensity),on.dfgLUT!==void 0&&(on.dfgLUT.value=lT()),Xi){if(mt.setValue(k,"toneMappingExposure",L.toneMappingExposure),Be.needsLights&&Br(on,hs),Ce&&Z.fog===!0&&Me.refreshFogUniforms(on,Ce),Me.refreshMaterialUniforms(on,Z,ye,ve,w.state.transmissionRenderTarget[T.id]),Be.needsLights&&Be.numLightProbeGrids>0){let zt=b,pn=0;for(let Bn of w.state.lightProbeGridArray)Bn.texture!==null&&(zt.textures[pn]=Bn.texture,zt.min[pn]=Bn.boundingBox.min,zt.max[pn]=Bn.boundingBox.max,zt.resolution[pn]=Bn.resolution,pn++);for(let Bn in zt)zt[Bn].length=pn;on.probesSH.value=zt.textures,on.probesMin.value=zt.min,on.probesMax.value=zt.max,on.probesResolution.value=zt.resolution}zo.upload(k,Is(Be),on,Ze)}if(Z.isShaderMaterial&&Z.uniformsNeedUpdate===!0&&(zo.upload(k,Is(Be),on,Ze),Z.uniformsNeedUpdate=!1),Z.isSpriteMaterial&&mt.setValue(k,"center",K.center),mt.setValue(k,"modelViewMatrix",K.modelViewMatrix),mt.setValue(k,"normalMatrix",K.normalMatrix),mt.setValue(k,"modelMatrix",K.matrixWorld),Z.uniformsGroups!==void 0){let zt=Z.uniformsGroups;for(let pn=0,Bn=zt.length;pn<Bn;pn++){let rl=zt[pn];$e.update(rl,fn),$e.bind(rl,fn)}}return fn}function Br(T,H){T.ambientLightColor.needsUpdate=H,T.lightProbe.needsUpdate=H,T.sunLights.needsUpdate=H,T.sunLightShadows.needsUpdate=H,T.directionalLights.needsUpdate=H,T.directionalLightShadows.needsUpdate=H,T.pointLights.needsUpdate=H,T.pointLightShadows.needsUpdate=H,T.spotLights.needsUpdate=H,T.spotLightShadows.needsUpdate=H,T.rectAreaLights.needsUpdate=H,T.hemisphereLights.needsUpdate=H}function Ps(T){return T.isMeshLambertMaterial||T.isMeshToonMaterial||T.isMeshPhongMaterial||T.isMeshStandardMaterial||T.isShadowMaterial||T.isShaderMaterial&&T.lights===!0}this.getActiveCubeFace=function(){return X},this.getActiveMipmapLevel=function(){return D},this.getRenderTarget=function(){return ne},this.setRenderTargetTextures=function(T,H,ee){let Z=We.get(T);Z.__autoAllocateDepthBuffer=T.resolveDepthBuffer===!1,Z.__autoAllocateDepthBuffer===!1&&(Z.__useRenderToTexture=!1),We.get(T.texture).__webglTexture=H,We.get(T.depthTexture).__webglTexture=Z.__autoAllocateDepthBuffer?void 0:ee,Z.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(T,H){let ee=We.get(T);ee.__webglFramebuffer=H,ee.__useDefaultFramebuffer=H===void 0},this.setRenderTarget=function(T,H=0,ee=0){ne=T,X=H,D=ee;let Z=null,K=!1,Ce=!1;if(T){let Ie=We.get(T);if(Ie.__useDefaultFramebuffer!==void 0){Ae.bindFramebuffer(k.FRAMEBUFFER,Ie.__webglFramebuffer),$.copy(T.viewport),re.copy(T.scissor),le=T.scissorTest,Ae.viewport($),Ae.scissor(re),Ae.setScissorTest(le),q=-1;return}else if(Ie.__webglFramebuffer===void 0)Ze.setupRenderTarget(T);else if(Ie.__hasExternalTextures)Ze.rebindTextures(T,We.get(T.texture).__webglTexture,We.get(T.depthTexture).__webglTexture);else if(T.depthBuffer){let rt=T.depthTexture;if(Ie.__boundDepthTexture!==rt){if(rt!==null&&We.has(rt)&&(T.width!==rt.image.width||T.height!==rt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Ze.setupDepthRenderbuffer(T)}}let De=T.texture;(De.isData3DTexture||De.isDataArrayTexture||De.isCompressedArrayTexture)&&(Ce=!0);let He=We.get(T).__webglFramebuffer;T.isWebGLCubeRenderTarget?(Array.isArray(He[H])?Z=He[H][ee]:Z=He[H],K=!0):T.samples>0&&Ze.useMultisampledRTT(T)===!1?Z=We.get(T).__webglMultisampledFramebuffer:Array.isArray(He)?Z=He[ee]:Z=He,$.copy(T.viewport),re.copy(T.scissor),le=T.scissorTest}else $.copy(Ne).multiplyScalar(ye).floor(),re.copy(qe).multiplyScalar(ye).floor(),le=Qe;if(ee!==0&&(Z=F),Ae.bindFramebuffer(k.FRAMEBUFFER,Z)&&Ae.drawBuffers(T,Z),Ae.viewport($),Ae.scissor(re),Ae.setScissorTest(le),K){let Ie=We.get(T.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_CUBE_MAP_POSITIVE_X+H,Ie.__webglTexture,ee)}else if(Ce){let Ie=H;for(let De=0;De<T.textures.length;De++){let He=We.get(T.textures[De]);k.framebufferTextureLayer(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0+De,He.__webglTexture,ee,Ie)}}else if(T!==null&&ee!==0){let Ie=We.get(T.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,Ie.__webglTexture,ee)}q=-1};function kr(T){let H=We.get(T);return(H.__readFormat!==T.format||H.__readType!==T.type)&&(H.__readFormat=T.format,H.__readType=T.type,H.__formatReadable=ht.textureFormatReadable(T.format),H.__typeReadable=ht.textureTypeReadable(T.type)),H}this.readRenderTargetPixels=function(T,H,ee,Z,K,Ce,Le,Ie=0){if(!(T&&T.isWebGLRenderTarget)){ot("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let De=We.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Le!==void 0&&(De=De[Le],Array.isArray(De)&&(De=De[0])),De){Ae.bindFramebuffer(k.FRAMEBUFFER,De);try{let He=T.textures[Ie],rt=He.format,yt=He.type;T.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+Ie);let Ge=kr(He);if(Ge.__formatReadable===!1){ot("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(Ge.__typeReadable===!1){ot("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}H>=0&&H<=T.width-Z&&ee>=0&&ee<=T.height-K&&k.readPixels(H,ee,Z,K,Se.convert(rt),Se.convert(yt),Ce)}finally{let He=ne!==null?We.get(ne).__webglFramebuffer:null;Ae.bindFramebuffer(k.FRAMEBUFFER,He)}}},this.readRenderTargetPixelsAsync=async function(T,H,ee,Z,K,Ce,Le,Ie=0){if(!(T&&T.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let De=We.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Le!==void 0&&(De=De[Le],Array.isArray(De)&&(De=De[0])),De)if(H>=0&&H<=T.width-Z&&ee>=0&&ee<=T.height-K){Ae.bindFramebuffer(k.FRAMEBUFFER,De);let He=T.textures[Ie],rt=He.format,yt=He.type;T.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+Ie);let Ge=kr(He);if(Ge.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(Ge.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let xt=k.createBuffer();k.bindBuffer(k.PIXEL_PACK_BUFFER,xt),k.bufferData(k.PIXEL_PACK_BUFFER,Ce.byteLength,k.STREAM_READ),k.readPixels(H,ee,Z,K,Se.convert(rt),Se.convert(yt),0),k.bindBuffer(k.PIXEL_PACK_BUFFER,null);let tn=ne!==null?We.get(ne).__webglFramebuffer:null;Ae.bindFramebuffer(k.FRAMEBUFFER,tn);let Bt=k.fenceSync(k.SYNC_GPU_COMMANDS_COMPLETE,0);return k.flush(),await k0(k,Bt,4),k.bindBuffer(k.PIXEL_PACK_BUFFER,xt),k.getBufferSubData(k.PIXEL_PACK_BUFFER,0,Ce),k.bindBuffer(k.PIXEL_PACK_BUFFER,null),k.deleteBuffer(xt),k.deleteSync(Bt),Ce}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(T,H=null,ee=0){let Z=Math.pow(2,-ee),K=Math.floor(T.image.width*Z),Ce=Math.floor(T.image.height*Z),Le=H!==null?H.x:0,Ie=H!==null?H.y:0;Ze.setTexture2D(T,0),k.copyTexSubImage2D(k.TEXTURE_2D,ee,0,0,Le,Ie,K,Ce),Ae.unbindTexture()},this.copyTextureToTexture=function(T,H,ee=null,Z=null,K=0,Ce=0){let Le,Ie,De,He,rt,yt,Ge,xt,tn,Bt=T.isCompressedTexture?T.mipmaps[Ce]:T.image;if(ee!==null)Le=ee.max.x-ee.min.x,Ie=ee.max.y-ee.min.y,De=ee.isBox3?ee.max.z-ee.min.z:1,He=ee.min.x,rt=ee.min.y,yt=ee.isBox3?ee.min.z:0;else{let mt=Math.pow(2,-K);Le=Math.floor(Bt.width*mt),Ie=Math.floor(Bt.height*mt),T.isDataArrayTexture?De=Bt.depth:T.isData3DTexture?De=Math.floor(Bt.depth*mt):De=1,He=0,rt=0,yt=0}Z!==null?(Ge=Z.x,xt=Z.y,tn=Z.z):(Ge=0,xt=0,tn=0);let kt=Se.convert(H.format),vn=Se.convert(H.type),Be;H.isData3DTexture?(Ze.setTexture3D(H,0),Be=k.TEXTURE_3D):H.isDataArrayTexture||H.isCompressedArrayTexture?(Ze.setTexture2DArray(H,0),Be=k.TEXTURE_2D_ARRAY):(Ze.setTexture2D(H,0),Be=k.TEXTURE_2D),Ae.activeTexture(k.TEXTURE0),Ae.pixelStorei(k.UNPACK_FLIP_Y_WEBGL,H.flipY),Ae.pixelStorei(k.UNPACK_PREMULTIPLY_ALPHA_WEBGL,H.premultiplyAlpha),Ae.pixelStorei(k.UNPACK_ALIGNMENT,H.unpackAlignment);let dn=Ae.getParameter(k.UNPACK_ROW_LENGTH),wt=Ae.getParameter(k.UNPACK_IMAGE_HEIGHT),cs=Ae.getParameter(k.UNPACK_SKIP_PIXELS),fn=Ae.getParameter(k.UNPACK_SKIP_ROWS),zr=Ae.getParameter(k.UNPACK_SKIP_IMAGES);Ae.pixelStorei(k.UNPACK_ROW_LENGTH,Bt.width),Ae.pixelStorei(k.UNPACK_IMAGE_HEIGHT,Bt.height),Ae.pixelStorei(k.UNPACK_SKIP_PIXELS,He),Ae.pixelStorei(k.UNPACK_SKIP_ROWS,rt),Ae.pixelStorei(k.UNPACK_SKIP_IMAGES,yt);let Xi=T.isDataArrayTexture||T.isData3DTexture,hs=H.isDataArrayTexture||H.isData3DTexture;if(T.isDepthTexture){let mt=We.get(T),on=We.get(H),Xn=We.get(mt.__renderTarget),zt=We.get(on.__renderTarget);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,Xn.__webglFramebuffer),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,zt.__webglFramebuffer);for(let pn=0;pn<De;pn++)Xi&&(k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,We.get(T).__webglTexture,K,yt+pn),k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,We.get(H).__webglTexture,Ce,tn+pn)),k.blitFramebuffer(He,rt,He+Le,rt+Ie,Ge,xt,Ge+Le,xt+Ie,k.DEPTH_BUFFER_BIT,k.NEAREST);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,null),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else if(K!==0||T.isRenderTargetTexture||We.has(T)){let mt=We.get(T),on=We.get(H);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,P),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,B);for(let Xn=0;Xn<De;Xn++)Xi?k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,mt.__webglTexture,K,yt+Xn):k.framebufferTexture2D(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,mt.__webglTexture,K),hs?k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,on.__webglTexture,Ce,tn+Xn):k.framebufferTexture2D(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,on.__webglTexture,Ce),K!==0?k.blitFramebuffer(He,rt,He+Le,rt+Ie,Ge,xt,Ge+Le,xt+Ie,k.COLOR_BUFFER_BIT,k.NEAREST):hs?k.copyTexSubImage3D(Be,Ce,Ge,xt,tn+Xn,He,rt,Le,Ie):k.copyTexSubImage2D(Be,Ce,Ge,xt,He,rt,Le,Ie);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,null),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else hs?T.isDataTexture||T.isData3DTexture?k.texSubImage3D(Be,Ce,Ge,xt,tn,Le,Ie,De,kt,vn,Bt.data):H.isCompressedArrayTexture?k.compressedTexSubImage3D(Be,Ce,Ge,xt,tn,Le,Ie,De,kt,Bt.data):k.texSubImage3D(Be,Ce,Ge,xt,tn,Le,Ie,De,kt,vn,Bt):T.isDataTexture?k.texSubImage2D(k.TEXTURE_2D,Ce,Ge,xt,Le,Ie,kt,vn,Bt.data):T.isCompressedTexture?k.compressedTexSubImage2D(k.TEXTURE_2D,Ce,Ge,xt,Bt.width,Bt.height,kt,Bt.data):k.texSubImage2D(k.TEXTURE_2D,Ce,Ge,xt,Le,Ie,kt,vn,Bt);Ae.pixelStorei(k.UNPACK_ROW_LENGTH,dn),Ae.pixelStorei(k.UNPACK_IMAGE_HEIGHT,wt),Ae.pixelStorei(k.UNPACK_SKIP_PIXELS,cs),Ae.pixelStorei(k.UNPACK_SKIP_ROWS,fn),Ae.pixelStorei(k.UNPACK_SKIP_IMAGES,zr),Ce===0&&H.generateMipmaps===!0&&H.mipmapsAutoUpdate===!0&&k.generateMipmap(Be),Ae.unbindTexture()},this.initRenderTarget=function(T){We.get(T).__webglFramebuffer===void 0&&Ze.setupRenderTarget(T)},this.initTexture=function(T){T.isCubeTexture?Ze.setTextureCube(T,0):T.isData3DTexture?Ze.setTexture3D(T,0):T.isDataArrayTexture||T.isCompressedArrayTexture?Ze.setTexture2DArray(T,0):Ze.setTexture2D(T,0),Ae.unbindTexture()},this.resetState=function(){X=0,D=0,ne=null,Ae.reset(),Te.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Ti}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorSpace=Tt._getDrawingBufferColorSpace(e),t.unpackColorSpace=Tt._getUnpackColorSpace()}};var E_={type:"change"},Pf={type:"start"},A_={type:"end"},qh=new tr,T_=new pi,hT=Math.cos(70*hf.DEG2RAD),En=new J,ii=2*Math.PI,Ut={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},If=1e-6,Yh=class extends Va{constructor(e,t=null){super(e,t),this.state=Ut.NONE,this.target=new J,this.cursor=new J,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:rr.ROTATE,MIDDLE:rr.DOLLY,RIGHT:rr.PAN},this.touches={ONE:or.ROTATE,TWO:or.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new J,this._lastQuaternion=new gi,this._lastTargetPosition=new J,this._quat=new gi().setFromUnitVectors(e.up,new J(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Do,this._sphericalDelta=new Do,this._scale=1,this._panOffset=new J,this._rotateStart=new ut,this._rotateEnd=new ut,this._rotateDelta=new ut,this._panStart=new ut,this._panEnd=new ut,this._panDelta=new ut,this._dollyStart=new ut,this._dollyEnd=new ut,this._dollyDelta=new ut,this._dollyDirection=new J,this._mouse=new ut,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=dT.bind(this),this._onPointerDown=uT.bind(this),this._onPointerUp=fT.bind(this),this._onContextMenu=vT.bind(this),this._onMouseWheel=gT.bind(this),this._onKeyDown=_T.bind(this),this._onTouchStart=yT.bind(this),this._onTouchMove=xT.bind(this),this._onMouseDown=pT.bind(this),this._onMouseMove=mT.bind(this),this._interceptControlDown=bT.bind(this),this._interceptControlUp=ST.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Ut.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(E_),this.update(),this.state=Ut.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){let t=this.object.position;En.copy(t).sub(this.target),En.applyQuaternion(this._quat),this._spherical.setFromVector3(En),this.autoRotate&&this.state===Ut.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(i)&&isFinite(s)&&(i<-Math.PI?i+=ii:i>Math.PI&&(i-=ii),s<-Math.PI?s+=ii:s>Math.PI&&(s-=ii),i<=s?this._spherical.theta=Math.max(i,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+s)/2?Math.max(i,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let o=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=o!=this._spherical.radius}if(En.setFromSpherical(this._spherical),En.applyQuaternion(this._quatInverse),t.copy(this.target).add(En),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let o=null;if(this.object.isPerspectiveCamera){let a=En.length();o=this._clampDistance(a*this._scale);let l=a-o;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){let a=new J(this._mouse.x,this._mouse.y,0);a.unproject(this.object);let l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;let c=new J(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(a),this.object.updateMatrixWorld(),o=En.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;o!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(o).add(this.object.position):(qh.origin.copy(this.object.position),qh.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(qh.direction))<hT?this.object.lookAt(this.target):(T_.setFromNormalAndCoplanarPoint(this.object.up,this.target),qh.intersectPlane(T_,this.target))))}else if(this.object.isOrthographicCamera){let o=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),o!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>If||8*(1-this._lastQuaternion.dot(this.object.quaternion))>If||this._lastTargetPosition.distanceToSquared(this.target)>If?(this.dispatchEvent(E_),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?ii/60*this.autoRotateSpeed*e:ii/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){En.setFromMatrixColumn(t,0),En.multiplyScalar(-e),this._panOffset.add(En)}_panUp(e,t){this.screenSpacePanning===!0?En.setFromMatrixColumn(t,1):(En.setFromMatrixColumn(t,0),En.crossVectors(this.object.up,En)),En.multiplyScalar(e),this._panOffset.add(En)}_pan(e,t){let i=this.domElement;if(this.object.isPerspectiveCamera){let s=this.object.position;En.copy(s).sub(this.target);let r=En.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/i.clientHeight,this.object.matrix),this._panUp(2*t*r/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let i=this.domElement.getBoundingClientRect(),s=e-i.left,r=t-i.top,o=i.width,a=i.height;this._mouse.x=s/o*2-1,this._mouse.y=-(r/a)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ii*this._rotateDelta.x/t.clientHeight),this._rotateUp(ii*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(ii*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-ii*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(ii*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-ii*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(i,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(i,s)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let i=this._getSecondPointerPosition(e),s=.5*(e.pageX+i.x),r=.5*(e.pageY+i.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ii*this._rotateDelta.x/t.clientHeight),this._rotateUp(ii*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(i,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let o=(e.pageX+t.x)*.5,a=(e.pageY+t.y)*.5;this._updateZoomParameters(o,a)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new ut,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,i={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}};function uT(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function dT(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function fT(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(A_),this.state=Ut.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function pT(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case rr.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=Ut.DOLLY;break;case rr.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Ut.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Ut.ROTATE}break;case rr.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Ut.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Ut.PAN}break;default:this.state=Ut.NONE}this.state!==Ut.NONE&&this.dispatchEvent(Pf)}function mT(n){switch(this.state){case Ut.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case Ut.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case Ut.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function gT(n){this.enabled===!1||this.enableZoom===!1||this.state!==Ut.NONE||(n.preventDefault(),this.dispatchEvent(Pf),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(A_))}function _T(n){this.enabled!==!1&&this._handleKeyDown(n)}function yT(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case or.ROTATE:if(this.enableRotate===!1){this.state=Ut.NONE;break}this._handleTouchStartRotate(n),this.state=Ut.TOUCH_ROTATE;break;case or.PAN:if(this.enablePan===!1){this.state=Ut.NONE;break}this._handleTouchStartPan(n),this.state=Ut.TOUCH_PAN;break;default:this.state=Ut.NONE}break;case 2:switch(this.touches.TWO){case or.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=Ut.TOUCH_DOLLY_PAN;break;case or.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=Ut.TOUCH_DOLLY_ROTATE;break;default:this.state=Ut.NONE}break;default:this.state=Ut.NONE}this.state!==Ut.NONE&&this.dispatchEvent(Pf)}function xT(n){switch(this._trackPointer(n),this.state){case Ut.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case Ut.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case Ut.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case Ut.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=Ut.NONE}}function vT(n){this.enabled!==!1&&n.preventDefault()}function bT(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function ST(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var Zh=256,Lf=(()=>{let n=new Float32Array(Zh*3),e=new gt;for(let t=0;t<Zh;t++)e.setHSL(.66*(1-t/(Zh-1)),.9,.55),n.set([e.r,e.g,e.b],t*3);return n})(),Kh=class{constructor(e){this.parent=e;this.renderer=new Wh({antialias:!1,preserveDrawingBuffer:!0}),this.renderer.setPixelRatio(Math.min(window.devicePixelRatio||1,2)),this.renderer.setClearColor(725014),e.appendChild(this.renderer.domElement),this.camera=new Kn(60,1,.05,200),this.camera.up.set(0,0,1),this.camera.position.set(-8,-8,7),this.controls=new Yh(this.camera,this.renderer.domElement),this.controls.addEventListener("change",()=>this.dirty=!0),this.points=new Da(this.geometry,new Po({size:.06,vertexColors:!0})),this.points.frustumCulled=!1,this.scene.add(this.points);let t=new Ga(20,20,3885658,1844785);t.rotation.x=Math.PI/2,this.scene.add(t,new Ha(1)),this.ro=new ResizeObserver(()=>this.resize()),this.ro.observe(e);let i=()=>{this.dirty&&this.render(),this.raf=requestAnimationFrame(i)};this.raf=requestAnimationFrame(i)}parent;renderer;scene=new Ia;camera;controls;geometry=new ni;points;capacity=0;cloud;dirty=!0;raf=0;ro;colourBy="height";onShown=null;pending=!1;pendingStamp=null;lastCount=0;resize(){let e=this.parent.clientWidth,t=Math.max(200,this.parent.clientHeight-4);this.renderer.setSize(e,t,!0),this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.dirty=!0}show(e){let t=performance.now();this.cloud=Hp(e,this.cloud);let i=this.cloud.count;i>this.capacity&&(this.capacity=Math.max(i,Math.ceil(this.capacity*1.5)),this.geometry.setAttribute("position",new mi(new Float32Array(this.capacity*3),3)),this.geometry.setAttribute("color",new mi(new Float32Array(this.capacity*3),3)));let s=this.geometry.getAttribute("position"),r=this.geometry.getAttribute("color");return s.array.set(this.cloud.positions.subarray(0,i*3)),this.colour(this.cloud,r.array,i),s.needsUpdate=!0,r.needsUpdate=!0,this.geometry.setDrawRange(0,i),this.lastCount=i,this.pending=!0,this.pendingStamp=Cl(e.header),vt.busyMs.cloudUnpack+=performance.now()-t,this.dirty=!0,i}colour(e,t,i){let s=this.colourBy==="intensity"&&i>0&&!Number.isNaN(e.intensity[0]),r=1/0,o=-1/0;for(let l=0;l<i;l++){let c=s?e.intensity[l]:e.positions[l*3+2];c<r&&(r=c),c>o&&(o=c)}let a=(Zh-1)/(o>r?o-r:1);for(let l=0;l<i;l++){let c=Math.round(((s?e.intensity[l]:e.positions[l*3+2])-r)*a)*3;t[l*3]=Lf[c],t[l*3+1]=Lf[c+1],t[l*3+2]=Lf[c+2]}}render(){this.dirty=!1;let e=performance.now();this.renderer.render(this.scene,this.camera),vt.busyMs.cloudRender+=performance.now()-e,this.pending&&this.onShown&&this.onShown(this.pendingStamp),this.pending=!1}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.controls.dispose(),this.geometry.dispose(),this.points.material.dispose(),this.renderer.dispose(),this.renderer.domElement.remove()}};function R_(n,e,t,i){let s=te("pre","config-effective","…"),r=te("div","config-changes"),o=te("textarea","config-editor");o.rows=8,o.spellcheck=!1,o.placeholder=`topics:
  /scan: { rate_limit_hz: 2 }`;let a=te("div","config-result"),l=In("apply change","",()=>{v()}),c=In("reload","small",()=>{g()}),h=te("div","config-controls");h.append(l,c);let d=te("div","config-edit");d.append(te("label","","change (YAML or JSON, the agent file's fields; only those listed below may change while it runs)"),o,h,a),n.append(r,d,s);let u=!0;function m(f){i.loaded=!0,i.mayChange=f.may_change,i.overlay=f.overlay??null,s.textContent=f.effective??f.error??"";let p=f.overlay??{},x=Object.keys(p).length,A=f.changed_by?` by ${f.changed_by}${f.changed_at_ms?`, ${new Date(f.changed_at_ms).toLocaleString()}`:""}`:"";r.textContent=x?`changes in force${A}:`:"no changes in force: the robot runs its file's configuration",x&&r.appendChild(te("pre","",JSON.stringify(p,null,2))),f.kept&&r.appendChild(te("div","info",`the hub keeps them and applies them again when ${t} reconnects (last by ${f.kept.by})`)),e.textContent=f.online?f.persisted?` · kept on the robot in ${f.persisted}`:" · not kept on the robot":" · offline",d.hidden=!f.may_change,l.disabled=!f.online,f.changeable&&(o.title=`may change while it runs: ${f.changeable.join(", ")}`),!o.value&&x&&(o.value=JSON.stringify(p,null,2))}async function g(){try{let f=await gn(`/api/v1/robots/${encodeURIComponent(t)}/config`);u&&m(f)}catch(f){if(!u)return;i.loaded=!0,s.textContent=`cannot read the configuration: ${f.message}`,d.hidden=!0}}async function v(){l.disabled=!0,a.className="config-result";try{let f=await gn(`/api/v1/robots/${encodeURIComponent(t)}/config`,{method:"PUT",body:o.value}),p=f.unchanged?"nothing changed":`applied: ${(f.changed??[]).join(", ")}`;a.textContent=p,a.classList.add("ok"),i.result=p,m({...f,may_change:!0,online:!0})}catch(f){let p=f instanceof fr?f.message:`${f.message}`;a.textContent=`refused: ${p}`,a.classList.add("error"),i.result=`refused: ${p}`}finally{l.disabled=!1}}return g(),()=>{u=!1}}function Or(n,e,t,i){(n instanceof HTMLButtonElement||n instanceof HTMLSelectElement)&&(n.disabled=!0),n.title=t,i.textContent=`Disabled: ${t}`,i.className="why",vt.disabled[e]=t}function C_(n,e,t,i,s,r){let o=`/${t}/`,a=te("div","task nav");a.appendChild(te("h3","","Navigation goal"));let l=te("p","muted","Looking for the robot's navigation action…"),c=te("progress");c.max=1,c.value=0;let h=te("div","navstate",""),d=In("Cancel goal","danger");d.disabled=!0,a.append(l,c,h,d);let u=te("div","task init");u.appendChild(te("h3","","Initial pose"));let m=In("Set initial pose: click the map"),g=te("p","muted",`publishes geometry_msgs/msg/PoseWithCovarianceStamped on ${o}initialpose`);u.append(m,g);let v=te("div","task svc");v.appendChild(te("h3","","Call a service"));let f=te("select"),p=te("form","svcform"),x=te("div","svcout"),A=te("p","muted","Listing the services you may call…");v.append(f,A,p,x),n.append(a,u,v);let b="goal",C=null,w=null,_=!1,M=!1;i.onClick=async(R,z)=>{if(b==="init"){if(b="goal",m.classList.remove("armed"),!M)return;let F=s()?.yaw??0;e.publish(`${o}initialpose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{pose:{position:{x:R,y:z,z:0},orientation:{x:0,y:0,z:Math.sin(F/2),w:Math.cos(F/2)}},covariance:new Array(36).fill(0)}},P=>Or(m,"initialpose",P,g)),g.textContent=`initial pose sent: (${Nt(R,2)}, ${Nt(z,2)})`;return}w?U(R,z):_&&(i.goal={x:R,y:z},i.invalidate(),e.publish(`${o}goal_pose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{position:{x:R,y:z,z:0},orientation:{x:0,y:0,z:0,w:1}}},F=>Or(a,"goal",F,l)),h.textContent=`goal published on ${o}goal_pose: (${Nt(R,2)}, ${Nt(z,2)})`)};function U(R,z){if(!w)return;let F=w;i.goal={x:R,y:z},i.invalidate();let P=s(),B=P?Math.hypot(P.x-R,P.y-z):1;c.value=0,h.textContent=`goal (${Nt(R,2)}, ${Nt(z,2)}) sent to ${F.name}…`;let X=e.sendGoal(F.name,F.type,{x:R,y:z},D=>{if(C!==X)return;let ne=Number(D?.distance_remaining);vt.feedback.push(ne),vt.feedback.length>500&&vt.feedback.splice(0,250),On("feedback"),Number.isFinite(ne)&&(c.value=B>0?Math.max(0,Math.min(1,1-ne/B)):1,h.textContent=`driving to (${Nt(R,2)}, ${Nt(z,2)}): ${Nt(ne,2)} m to go`)});C=X,d.disabled=!1,X.result.then(D=>{if(vt.lastResult=D,C!==X)return;let ne=D.status===4?"reached":D.status===5?"canceled":D.status===6?"aborted":`ended (status ${D.status})`,q=D.values??{};h.textContent=`goal ${ne}${q.x!=null?` at (${Nt(q.x,2)}, ${Nt(q.y,2)})`:""}`,D.status===4&&(c.value=1),d.disabled=!0,C=null},D=>{C===X&&(C=null,d.disabled=!0,D instanceof Vs&&/not allowed/.test(D.message)?Or(a,"navigate",D.message,l):h.textContent=`goal failed: ${D.message}`)})}d.addEventListener("click",()=>{C?.cancel(),h.textContent+=" · cancel requested"}),m.addEventListener("click",()=>{b=b==="init"?"goal":"init",m.classList.toggle("armed",b==="init")}),r.push(()=>C?.cancel()),(async()=>{let[R,z]=await Promise.all([e.call("/rosapi/action_servers").then(D=>D.action_servers??[],()=>[]),e.call("/rosapi/services").then(D=>D.services??[],()=>[])]),F=R.filter(D=>D.startsWith(o)),P=F.find(D=>/navigate/.test(D))??F[0];if(P){let D=await e.call("/rosapi/service_type",{service:P}).then(ne=>String(ne.type??""),()=>"");w={name:P,type:D},l.textContent=`Click on the map to send a goal to ${P} (${D}).`}else{let D=await e.advertise(`${o}goal_pose`,"geometry_msgs/msg/PoseStamped");D?Or(d,"navigate",`the hub lists no navigation action you may use on ${t}, and refused the goal topic: ${D}`,l):(_=!0,r.push(()=>e.unadvertise(`${o}goal_pose`)),l.textContent=`No navigation action listed for you; clicks publish a PoseStamped on ${o}goal_pose.`)}let B=await e.advertise(`${o}initialpose`,"geometry_msgs/msg/PoseWithCovarianceStamped");B?Or(m,"initialpose",B,g):(M=!0,r.push(()=>e.unadvertise(`${o}initialpose`)));let X=z.filter(D=>D.startsWith(o));if(X.length===0){Or(f,"services",`the hub lists no services of ${t} you may call (/rosapi/services)`,A);return}for(let D of X)f.appendChild(new Option(D,D));A.textContent="",f.addEventListener("change",()=>L(f.value)),L(X[0])})();async function L(R){p.replaceChildren(te("p","muted","loading the request type…")),x.replaceChildren();let z="",F=[];try{z=String((await e.call("/rosapi/service_type",{service:R})).type),F=(await e.call("/rosapi/service_request_details",{type:z})).typedefs??[]}catch(ne){p.replaceChildren(te("p","why",`cannot read the type of ${R}: ${ne.message}`));return}let P=Wp(F);p.replaceChildren(te("div","muted",`${z} request`));let B=[],X=(ne,q,W)=>{q&&q.fieldnames.forEach(($,re)=>{let le=q.fieldtypes[re],Q=F.find(ve=>ve.type===le);if(Q&&q.fieldarraylen[re]===-1)return X(ne[$],Q,[...W,$]);let me=te("label","",`${[...W,$].join(".")} (${le}${q.fieldarraylen[re]>=0?"[]":""})`),fe=te("input");fe.name=[...W,$].join("."),le==="bool"&&q.fieldarraylen[re]===-1?fe.type="checkbox":fe.value=JSON.stringify(ne[$]),me.appendChild(fe),p.appendChild(me),B.push({path:[...W,$],input:fe,kind:le==="bool"&&q.fieldarraylen[re]===-1?"bool":le==="string"&&q.fieldarraylen[re]===-1?"string":"json"})})};X(P,F[0],[]),B.length===0&&p.appendChild(te("p","muted","(no request fields)"));for(let ne of B)ne.kind==="string"&&(ne.input.value="");let D=In("Call","primary");D.type="submit",p.appendChild(D),p.onsubmit=async ne=>{ne.preventDefault();let q=structuredClone(P);try{for(let W of B){let $=q;for(let le of W.path.slice(0,-1))$=$[le];let re=W.path[W.path.length-1];$[re]=W.kind==="bool"?W.input.checked:W.kind==="string"?W.input.value:JSON.parse(W.input.value||"null")}}catch(W){x.replaceChildren(te("p","why",`bad value: ${W.message}`));return}D.disabled=!0,x.replaceChildren(te("p","muted",`calling ${R}…`));try{let W=await e.call(R,q,10);vt.lastServiceResponse={service:R,ok:!0,values:W},On("service-response"),x.replaceChildren(te("div","ok","response:"),Jr(W))}catch(W){vt.lastServiceResponse={service:R,ok:!1,error:W.message},x.replaceChildren(te("p","why",`refused or failed: ${W.message}`)),W instanceof Vs&&/not allowed/.test(W.message)&&Or(D,`call:${R}`,W.message,A)}finally{vt.disabled[`call:${R}`]||(D.disabled=!1)}}}}function Cs(n,e,t=""){let i=te("section",`panel ${t}`),s=te("h2","",e),r=te("span","info");s.appendChild(r);let o=te("div","body");return i.append(s,o),n.appendChild(i),{box:i,body:o,info:r}}var Nf=class{n=0;lastLatency=NaN;note(e){this.n++;let t=Cl(e?.header);t!=null&&(this.lastLatency=Date.now()-t)}};function I_(n,e,t){n.innerHTML="";let i=[],s=new Map,r=F=>{let P=s.get(F);return P||s.set(F,P=new Nf),P},o=te("div","robot-title");o.append(te("a","back","← fleet"),te("h1","",t),te("span","badge","…")),o.firstChild.href="#/",n.appendChild(o);let a=o.lastChild,l=te("div","robot-grid");n.appendChild(l);let c=Cs(l,"Map (odometry path, scan, markers, goal)","wide"),h=new jr(c.body);h.selected=t,h.canvas.id="robot-map",vt.mapToScreen=(F,P)=>h.toScreen(F,P),i.push(()=>h.destroy(),()=>vt.mapToScreen=null);let d=Cs(l,"Tasking","tasking"),u=Cs(l,"Laser scan"),m=Cs(l,"Point cloud (3D)"),g=Cs(l,"Camera"),v=Cs(l,"Topics","full"),f=Cs(l,"Inspector","inspector"),p=Cs(l,"Link quality (last 5 minutes)","wide"),x=Cs(l,"Configuration","full config");vt.config={loaded:!1,mayChange:!1,overlay:null,result:""},i.push(R_(x.body,x.info,t,vt.config));let A=null,b=!1;function C(F){b=!0;let P=F.filter(pe=>pe.name.startsWith(`/${t}/`)),B=pe=>P.filter(Xe=>Xe.type===pe),X="#2f80ed",D=Au(t,F),ne=B("nav_msgs/msg/Odometry")[0];for(let pe of[D,ne&&{topic:ne.name,type:ne.type}])pe&&i.push(e.subscribe(pe.topic,Xe=>{if(r(pe.topic).note(Xe),pe.topic===ne?.name&&On("odom"),pe.topic!==D?.topic)return;let et=Il(Xe);et&&(A=et,h.setPose(t,et,X),vt.poses[t]={...et,at:Date.now()},On("pose"))},{type:pe.type,throttle_rate:50,queue_length:1,compression:"none"}));D||(c.info.textContent="no pose or odometry topic");let q=[...B("visualization_msgs/msg/MarkerArray"),...B("visualization_msgs/msg/Marker")];for(let pe of q){let Xe=new Pl;h.markers.push(Xe),i.push(e.subscribe(pe.name,et=>{r(pe.name).note(Array.isArray(et?.markers)?et.markers[0]:et),Xe.apply(et,performance.now()),h.invalidate(),On("markers")},{type:pe.type,queue_length:10}))}D&&(c.info.textContent=`${D.topic}${q.length?` · markers: ${q.map(pe=>pe.name).join(", ")}`:""}`);let W=B("sensor_msgs/msg/LaserScan")[0];if(W){let pe=te("canvas","scan");u.body.appendChild(pe);let Xe=null,et=10,Gt=!1;i.push(e.subscribe(W.name,dt=>{if(r(W.name).note(dt),Xe=Gp(dt),et=dt.range_max||et,Gt=!0,On("scan"),A){let Pt=Math.cos(A.yaw),At=Math.sin(A.yaw),pt=new Float32Array(Xe.length);for(let k=0;k<Xe.length;k+=2)pt[k]=A.x+Pt*Xe[k]-At*Xe[k+1],pt[k+1]=A.y+At*Xe[k]+Pt*Xe[k+1];h.scan=pt,h.invalidate()}},{type:W.type,queue_length:1}));let Rt=0,cn=()=>{if(Rt=requestAnimationFrame(cn),!Gt||!Xe)return;Gt=!1;let dt=devicePixelRatio||1,Pt=pe.clientWidth,At=pe.clientHeight;pe.width=Pt*dt,pe.height=At*dt;let pt=pe.getContext("2d");pt.setTransform(dt,0,0,dt,0,0),pt.fillStyle="#0b1016",pt.fillRect(0,0,Pt,At);let k=Math.min(Pt,At)/2/Math.min(et,15);pt.strokeStyle="#1f2a35";for(let be=2;be<=14;be+=2)pt.beginPath(),pt.arc(Pt/2,At/2,be*k,0,7),pt.stroke();pt.fillStyle="#f2c94c";for(let be=0;be<Xe.length;be+=2)pt.fillRect(Pt/2-Xe[be+1]*k-1,At/2-Xe[be]*k-1,2,2);pt.fillStyle="#2f80ed",pt.beginPath(),pt.moveTo(Pt/2,At/2-10),pt.lineTo(Pt/2-6,At/2+6),pt.lineTo(Pt/2+6,At/2+6),pt.fill(),u.info.textContent=`${W.name} · ${Xe.length/2} points · 2 m rings`};Rt=requestAnimationFrame(cn),i.push(()=>cancelAnimationFrame(Rt))}else u.body.appendChild(te("p","muted","This robot publishes no LaserScan."));let $=B("sensor_msgs/msg/PointCloud2")[0];if($){let pe=new Kh(m.body),Xe=te("select");for(let et of["height","intensity"])Xe.appendChild(new Option(`colour by ${et}`,et));Xe.addEventListener("change",()=>pe.colourBy=Xe.value),m.box.querySelector("h2").appendChild(Xe),pe.onShown=et=>{et!=null&&vt.cloudAgesMs.push(Date.now()-et),vt.cloudAgesMs.length>2e3&&vt.cloudAgesMs.splice(0,1e3),On("cloud-rendered")},i.push(e.subscribe($.name,et=>{r($.name).note(et);let Gt=pe.show(et);On("cloud"),m.info.textContent=`${$.name} · ${Gt.toLocaleString()} points`},{type:$.type,queue_length:1})),i.push(()=>pe.destroy())}else m.body.appendChild(te("p","muted","This robot publishes no PointCloud2."));let re=Cg(g,e,P,i,(pe,Xe)=>r(pe).note(Xe)),le=te("select"),Q=te("div","tree");f.body.append(le,Q);let me=new Set([W?.name,$?.name,D?.topic,...q.map(pe=>pe.name),...re]),fe=P.find(pe=>!me.has(pe.name)&&pe.rate_hz>0)??P.find(pe=>!me.has(pe.name))??P[0];for(let pe of P)le.appendChild(new Option(`${pe.name} (${pe.type})`,pe.name));fe&&(le.value=fe.name);let ve=null,ye=null,Ve=0,Je=0,Ne=performance.now(),qe=()=>{ve?.();let pe=P.find(Xe=>Xe.name===le.value);pe&&(Je=0,Ne=performance.now(),ye=null,Q.textContent="waiting for a message…",ve=e.subscribe(pe.name,(Xe,et,Gt)=>{r(pe.name).note(Xe),ye=Xe,Ve=Gt,Je++,On("inspector")},{type:pe.type,queue_length:1,throttle_rate:200}))};le.addEventListener("change",qe),qe();let Qe=window.setInterval(()=>{if(!ye)return;let pe=Je/((performance.now()-Ne)/1e3),Xe=r(le.value).lastLatency;f.info.textContent=`${Nt(pe)} msg/s shown · latency ${Nt(Xe,0)} ms · ${Math.round(performance.now()-Ve)} ms ago`,Q.replaceChildren(Jr(Al(ye),le.value))},1e3);i.push(()=>{clearInterval(Qe),ve?.()}),C_(d.body,e,t,h,()=>A,i)}let w=te("table","topics");w.innerHTML="<thead><tr><th>topic</th><th>type</th><th>rate (hub)</th><th>bandwidth (hub)</th><th>latency (here)</th><th>drops</th></tr></thead>";let _=te("tbody");w.appendChild(_),v.body.appendChild(w);let M=new Map,U=new wr(3,300),L=new ql(p.body,U,[{label:"RTT ms",colour:"#f2994a",scale:"ms"},{label:"latency ms",colour:"#eb5757",scale:"ms"},{label:"link MB/s",colour:"#27ae60",scale:"r"}],Math.max(400,p.body.clientWidth||900),180);i.push(()=>L.destroy());async function R(){let F,P;try{[{robots:F},{topics:P}]=await Promise.all([gn("/api/v1/robots"),gn("/api/v1/topics")])}catch($){a.textContent=`cannot read the hub: ${$.message}`;return}let B=F.find($=>$.name===t);a.textContent=B?B.online?"online":"offline":"not visible to you",a.className=`badge ${B?.online?"ok":"off"}`,n.classList.toggle("offline",!!B&&!B.online),!b&&B?.online&&C(P);let X=Date.now()/1e3;B?.online&&U.push(X,B.rtt_ms??null,B.latency_ms??null,B.link_rate_bps!=null?B.link_rate_bps/1e6:null);let D=B?.budget,ne=D?[D.max_bps!=null?`${zn(D.max_bps)}`:"",D.day_bytes!=null?`${Nt(D.day_bytes/1e6,0)} MB/day`:""].filter($=>$):[];p.info.textContent=D?` · budget ${ne.join(" and ")}: using ${zn(D.use_bps)}${D.thinned.length?`, thinning ${D.thinned.length} topic${D.thinned.length>1?"s":""}`:""}`:"";let q=B?.link_estimate_age_s;B?.online&&q!=null&&q>=10?p.info.textContent+=` · capacity ${B.capacity_bps?zn(B.capacity_bps):"not known"}, measured ${_r(Date.now()-q*1e3)} (idle since)`:B?.online&&q==null&&(p.info.textContent+=" · link capacity not measured with data yet");let W=B?.mirrors??[];p.info.textContent+=W.map($=>{let re=B?.capacity_bps?` of ${zn(B.capacity_bps)}`:"",le=$.offload.fits===null?"link capacity not known yet":$.offload.fits?"fits the link: offload":"does not fit the link";return` · mirror ${$.name} reads ${$.reads.length} topic${$.reads.length===1?"":"s"}, ${zn($.inputs_bps)}${re}: ${le}`}).join(""),p.info.title=W.length?W[0].offload.rule:"",L.update();for(let $ of P.filter(re=>re.name.startsWith(`/${t}/`))){let re=M.get($.name);if(!re){let Ne=te("tr"),qe=Array.from({length:6},()=>te("td")),Qe=te("span","",$.name);qe[0].append(Qe),qe[1].textContent=$.type,Ne.append(...qe),_.appendChild(Ne);let pe=[new wr(1,120),new wr(1,120),new wr(1,120)];re={name:Qe,cell:qe[0],pull:null,rate:new co(qe[2],pe[0],"#2f80ed"),bw:new co(qe[3],pe[1],"#27ae60"),lat:new co(qe[4],pe[2],"#eb5757"),s:pe,drops:qe[5]},M.set($.name,re)}let le=$.state==="idle"||$.state==="pull"?$.state:$.thinned?"thinned":"";if(re.name.textContent=le?`${$.name} (${le})`:$.name,re.name.title=$.state==="idle"?"nobody is subscribed: the robot holds this topic back":$.state==="pull"?"sent only when asked: one message per pull":$.thinned?"the robot's data budget holds this topic back (lowest priorities first)":"",$.state==="pull"&&!re.pull){let Ne=te("div","pulled"),qe=$.name,Qe=In("pull","small",async()=>{Qe.disabled=!0;try{let pe=qe.slice(t.length+2),Xe=await gn(`/api/v1/robots/${encodeURIComponent(t)}/topics/${pe}/pull`,{method:"POST"});Ne.replaceChildren(Jr(Xe.msg,qe))}catch(pe){Ne.textContent=`pull failed: ${pe.message}`}finally{Qe.disabled=!1}});re.cell.append(" ",Qe,Ne),re.pull=Qe}let Q=s.get($.name)?.lastLatency??NaN;re.s[0].push(X,$.rate_hz),re.s[1].push(X,$.bandwidth_bps),re.s[2].push(X,Number.isFinite(Q)?Q:null);let me=$.offered_rate_hz,fe=$.predicted_rate_hz,ve=me!=null&&fe!=null&&fe<me*.98;re.rate.update(ve?`${Nt($.rate_hz)} Hz · link carries ~${Nt(fe)} of ${Nt(me)} offered`:`${Nt($.rate_hz)} Hz`),re.cell.parentElement?.children[2]?.setAttribute("title",me==null?"":`offered on the robot: ${Nt(me)} Hz`+(fe==null?"":`; predicted over its link: ${Nt(fe)} Hz`));let ye=$.compression_ratio??1;re.bw.update(ye>=1.05&&$.link_bandwidth_bps!=null?`${zn($.bandwidth_bps)} · link ${zn($.link_bandwidth_bps)} (${Nt(ye,1)}×)`:zn($.bandwidth_bps)),re.lat.update(Number.isFinite(Q)?`${Nt(Q,0)} ms`:"not subscribed");let Ve=Object.entries($.drops??{}).filter(([,Ne])=>Ne).map(([Ne,qe])=>`${Ne} ${qe}`),Je=Object.entries($.robot_drops??{}).filter(([,Ne])=>Ne).map(([Ne,qe])=>`${Ne} ${qe}`);re.drops.textContent=[...Ve,...Je.length?[`on the robot: ${Je.join(", ")}`]:[]].join("; ")||"0"}}R();let z=window.setInterval(R,1e3);return i.push(()=>clearInterval(z),()=>M.forEach(F=>{F.rate.destroy(),F.bw.destroy(),F.lat.destroy()})),()=>i.forEach(F=>F())}var Hi=n=>document.getElementById(n),nl=Hi("main"),P_=Hi("conn"),MT=Hi("who"),L_=Hi("signin"),N_=Hi("signout"),Df=Hi("estop"),Uf=Hi("estop-note"),Of=Hi("login");function D_(){try{let n=JSON.parse(localStorage.getItem("fleetlink.estop")??"null");if(n?.topic&&n?.type)return n}catch{}return{topic:"/fleet/estop",type:"std_msgs/msg/Bool"}}var cr,il=()=>{};function Ff(){cr?.close(),cr=new El(Si.wsUrl()),globalThis.fleetlinkRosbridge=cr,cr.onState=(e,t)=>{P_.textContent=e==="open"?"connected":e==="connecting"?"connecting…":`disconnected (${t}), retrying`,P_.className=`conn ${e}`,e==="open"&&wT()};let n=Si.principal();MT.textContent=n==="token"?"signed in with a token":n?`signed in as ${n}`:"anonymous (read-only where the hub allows)",L_.hidden=!!n,N_.hidden=!n}async function wT(){let n=D_(),e=await cr.advertise(n.topic,n.type);Df.disabled=!!e,Df.title=e?`Disabled: ${e}`:`publishes ${n.type} {data: true} on ${n.topic}`,Uf.textContent=e?`e-stop disabled: ${e}`:`→ ${n.topic}`,e?vt.disabled.estop=e:delete vt.disabled.estop}Df.addEventListener("click",()=>{let n=D_(),e=n.type.endsWith("/Bool")?{data:!0}:{};for(let t=0;t<3;t++)setTimeout(()=>cr.publish(n.topic,e,i=>Uf.textContent=`e-stop refused: ${i}`),t*100);Uf.textContent=`e-stop sent on ${n.topic} at ${new Date().toLocaleTimeString()}`});function Jh(){il();let n=location.hash.replace(/^#\/?/,"");document.querySelectorAll("nav a").forEach(e=>e.classList.toggle("active",e.hash===`#/${n.split("/")[0]}`)),nl.classList.remove("offline"),n.startsWith("robot/")?il=I_(nl,cr,decodeURIComponent(n.slice(6))):n==="admin"?il=Fp(nl):n==="recordings"?il=kp(nl):il=jp(nl,cr,e=>location.hash=`#/robot/${encodeURIComponent(e)}`)}L_.addEventListener("click",()=>Of.showModal());Hi("login-cancel").addEventListener("click",()=>Of.close());Hi("login-form").addEventListener("submit",async n=>{n.preventDefault();let e=n.target,t=e.elements.namedItem("user").value,i=e.elements.namedItem("password").value,s=e.elements.namedItem("token").value.trim(),r=Hi("login-error");r.textContent="";try{if(s){let o=await fetch("/api/v1/robots",{headers:{Authorization:`Bearer ${s}`}});if(!o.ok)throw new fr(o.status,(await o.json().catch(()=>null))?.error??`HTTP ${o.status}`);Si.set(s,"token")}else{let o=await gn("/api/v1/login",{method:"POST",body:JSON.stringify({user:t,password:i})});Si.set(o.token,o.principal)}e.reset(),Of.close(),Ff(),Jh()}catch(o){r.textContent=`sign-in refused: ${o.message}`}});N_.addEventListener("click",async()=>{Si.principal()!=="token"&&await gn("/api/v1/logout",{method:"POST"}).catch(()=>{}),Si.clear(),Ff(),Jh()});window.addEventListener("hashchange",Jh);Ff();Jh();var U_=()=>{vt.renders++,requestAnimationFrame(U_)};requestAnimationFrame(U_);
